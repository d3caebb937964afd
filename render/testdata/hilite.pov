#version 3.7; global_settings { assumed_gamma 1.0 }
camera { location <0,0,-5> }
light_source { <-3,4,-6> rgb <1,0.9,0.8> }
light_source { <4,1,-3> rgb 0.5 fade_distance 4 fade_power 2 }
sphere { <-1.1,0,0>, 1 pigment { rgb <0.8,0.3,0.2> } finish { phong 0.8 phong_size 20 } }
sphere { <1.1,0,0>, 1 pigment { rgb <0.2,0.5,0.9> } finish { specular 0.7 roughness 0.02 brilliance 2 metallic 0.7 } }
