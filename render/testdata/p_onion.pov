camera { orthographic location <0,10,0> direction -y up z*6 right x*6 }
plane { y, 0 pigment { onion frequency 2 phase 0.1 } finish { ambient 1 diffuse 0 } }
