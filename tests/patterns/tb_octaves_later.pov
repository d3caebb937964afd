// octaves written after a warp still edit the classic turbulence
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
plane { z, 0.37
  pigment { bozo turbulence 0.5 warp { turbulence 0.2 } scale 0.4 octaves 2 omega 0.7 }
  finish { ambient 1 diffuse 0 }
}
