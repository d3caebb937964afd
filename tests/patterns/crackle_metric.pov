// crackle with metric 3, a form and an offset
#version 3.7;
global_settings { assumed_gamma 1  }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
plane { z, 0.37
  pigment { crackle metric 3 form <-1, 0.5, 0.5> offset 0.2 scale 0.4 }
  finish { ambient 1 diffuse 0 }
}
