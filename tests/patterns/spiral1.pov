// spiral1 (3 arms, the number truncated) with turbulence
#version 3.7;
global_settings { assumed_gamma 1  }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
plane { z, 0.37
  pigment { spiral1 3.7 turbulence 0.2 scale 0.4 color_map { [0 rgb 0] [1 rgb <1, 0.7, 0.3>] } }
  finish { ambient 1 diffuse 0 }
}
