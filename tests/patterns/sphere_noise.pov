// granite on a sphere: the noise varies in all three dimensions
#version 3.7;
global_settings { assumed_gamma 1  }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
sphere { 0, 1.4
  pigment { granite scale 0.8 turbulence 0.2 }
  finish { ambient 1 diffuse 0 }
}
