// marble: turbulence inside the formula, triangle wave, default map
#version 3.7;
global_settings { assumed_gamma 1  }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
plane { z, 0.37
  pigment { marble turbulence 0.5 scale 0.5 }
  finish { ambient 1 diffuse 0 }
}
