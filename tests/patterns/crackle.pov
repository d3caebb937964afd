// crackle with its defaults (form <-1, 1, 0>, metric 2)
#version 3.7;
global_settings { assumed_gamma 1  }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
plane { z, 0.37
  pigment { crackle scale 0.4 }
  finish { ambient 1 diffuse 0 }
}
