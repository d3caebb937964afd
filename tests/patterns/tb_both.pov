// classic and warp turbulence together
#version 3.7;
global_settings { assumed_gamma 1  }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
plane { z, 0.37
  pigment { bozo warp { turbulence <0.4, 0, 0> } scale 0.5 turbulence 0.3 }
  finish { ambient 1 diffuse 0 }
}
