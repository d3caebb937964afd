camera { orthographic location <0,10,0> direction -y up z*24 right x*24 }
plane { y, 0.3 pigment { brick } finish { ambient 1 diffuse 0 } }
