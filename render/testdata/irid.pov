#version 3.7; global_settings { assumed_gamma 1.0 irid_wavelength <0.6,0.5,0.35> }
camera { location <0,0,-5> }
light_source { <-3,4,-6> rgb 1 }
light_source { <4,0,-2> rgb 0.4 }
sphere { <-1.1,0,0>, 1 pigment { rgb 0.8 } finish { phong 0.6 irid { 0.4 thickness 0.3 } } }
sphere { <1.1,0,0>, 1 pigment { rgb 1 } finish { diffuse 0.5 irid { 0.7 thickness 0.8 } } }
