camera { orthographic location <0,10,0> direction -y up z*4 right x*4 }
plane { y, 0 pigment { gradient x sine_wave } finish { ambient 1 diffuse 0 } }
