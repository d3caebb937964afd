camera { orthographic location <0,10,0> direction -y up z*24 right x*24 }
plane { y, 4.1 pigment { brick } finish { ambient 1 diffuse 0 } }
