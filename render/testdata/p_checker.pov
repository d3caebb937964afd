camera { orthographic location <0,10,0> direction -y up z*6 right x*6 }
plane { y, 0 pigment { checker rgb <1,0,0> rgb <0,0,1> } finish { ambient 1 diffuse 0 } }
