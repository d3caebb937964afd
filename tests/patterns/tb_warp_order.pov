// warp turbulence between transforms: applied in the order written
#version 3.7;
global_settings { assumed_gamma 1  }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
plane { z, 0.37
  pigment { bozo scale 0.3 warp { turbulence 0.5 octaves 4 lambda 2.5 } translate <0.5, 0, 0> }
  finish { ambient 1 diffuse 0 }
}
