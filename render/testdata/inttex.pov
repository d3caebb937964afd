#version 3.7; global_settings { assumed_gamma 1.0 }
camera { location <0,0,-2> look_at <0,0,0> }
light_source { <1,1,-1> rgb 1 }
sphere { 0, 4 pigment { rgb <1,0,0> } interior_texture { pigment { rgb <0,1,0> } } }
sphere { <0.5,0,1>, 0.5 pigment { rgb 1 } interior_texture { pigment { rgb <0,0,1> } } }
sphere { <-0.6,0.2,0.5>, 0.4 pigment { rgbt 1 } interior_texture { pigment { rgb <0,0,0> } } }
