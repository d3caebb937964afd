// marble far from the origin: the wave's period is 1.00001
#version 3.7;
global_settings { assumed_gamma 1  }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
plane { z, 0.37
  pigment { marble scale 0.1 translate <10000, 0, 0> }
  finish { ambient 1 diffuse 0 }
}
