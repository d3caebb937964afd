#version 3.7; global_settings { assumed_gamma 1.0 }
camera { location <0,1,-5> look_at <0,0.5,0> }
light_source { <0,5,-2> rgb 1.5 spotlight point_at <0,-1,1> radius 15 falloff 35 tightness 5 fade_distance 3 fade_power 2 }
light_source { <3,3,-3> rgb <0.3,0.3,0.6> fade_distance 1.5 fade_power 1 shadowless }
plane { y, -1 pigment { rgb 0.9 } }
sphere { <0,0,1>, 1 pigment { rgb <0.9,0.5,0.3> } finish { phong 0.6 } }
