#version 3.7; global_settings { assumed_gamma 1.0 }
camera { location <0,1,-5> look_at <0,0.5,0> }
light_source { <-2,5,-3> rgb 1 area_light <2,0,0>, <0,0,2>, 3, 3 }
plane { y, -1 pigment { rgb 0.9 } }
sphere { <0,0,0>, 1 pigment { rgb <0.9,0.5,0.3> } }
