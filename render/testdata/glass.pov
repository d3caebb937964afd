#version 3.7; global_settings { assumed_gamma 1.0 }
camera { location <0,1,-5> look_at <0,0.5,0> }
light_source { <-4,6,-5> rgb 1 }
background { rgb <0.2,0.3,0.5> }
plane { y, -1 pigment { checker rgb 1 rgb <0.1,0.1,0.1> } }
sphere { <-1,0,0>, 1 pigment { rgbf <1,1,1,0.9> } finish { phong 0.9 reflection { 0.05, 1 fresnel } conserve_energy } interior { ior 1.5 } }
sphere { <1.2,0,0.5>, 1 pigment { rgbt <0.8,1,0.8,0.8> } interior { ior 1.3 fade_distance 1 fade_power 2 fade_color <0.5,0.2,0.2> } }
