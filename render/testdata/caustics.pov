#version 3.7; global_settings { assumed_gamma 1.0 }
camera { location <0,1,-5> look_at <0,0.5,0> }
light_source { <-2,6,-3> rgb 1 }
plane { y, -1 pigment { rgb 0.9 } }
sphere { <0,0,0>, 0.9 pigment { rgbf <1,1,1,0.9> } interior { ior 1.5 caustics 1.0 } }
