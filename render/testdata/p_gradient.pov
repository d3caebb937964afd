camera { orthographic location <0,10,0> direction -y up z*4 right x*4 }
plane { y, 0 pigment { gradient <1,0,1> color_map { [0 rgb <1,0,0>] [0.3 rgb <0,1,0>] [0.3 rgb <0,0,1>] [1 rgb 1] } scale 1.5 translate <0.2,0,0.1> } finish { ambient 1 diffuse 0 } }
