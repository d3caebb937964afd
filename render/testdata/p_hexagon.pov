camera { orthographic location <0,10,0> direction -y up z*8 right x*8 }
plane { y, 0 pigment { hexagon } finish { ambient 1 diffuse 0 } }
