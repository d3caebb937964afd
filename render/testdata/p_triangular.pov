camera { orthographic location <0,10,0> direction -y up z*7 right x*7 }
plane { y, 0 pigment { triangular } finish { ambient 1 diffuse 0 } }
