// wood with vector turbulence, default map
#version 3.7;
global_settings { assumed_gamma 1  }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
plane { z, 0.37
  pigment { wood turbulence <0.1, 0.2, 0> scale 0.3 translate <0.5, 0, 0> }
  finish { ambient 1 diffuse 0 }
}
