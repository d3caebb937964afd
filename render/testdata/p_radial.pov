camera { orthographic location <0,10,0> direction -y up z*2 right x*2 }
plane { y, 0 pigment { radial } finish { ambient 1 diffuse 0 } }
