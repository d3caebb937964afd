// classic turbulence with octaves, omega and lambda (omega and lambda in single precision)
#version 3.7;
global_settings { assumed_gamma 1  }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
plane { z, 0.37
  pigment { bozo turbulence 0.6 octaves 3 omega 0.6 lambda 2.2 scale 0.4 }
  finish { ambient 1 diffuse 0 }
}
