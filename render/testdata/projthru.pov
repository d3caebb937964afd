#version 3.7; global_settings { assumed_gamma 1.0 }
camera { location <0,3,-4> look_at <0,0,0> }
light_source { <0,6,0> rgb 1 projected_through { sphere { <0.5,3,0>, 1 } } }
light_source { <-3,4,-3> rgb 0.3 shadowless projected_through { sphere { <-1.5,2,-1.5>, 0.5 } } }
plane { y, 0 pigment { rgb 1 } }
sphere { <1,0.5,0>, 0.5 pigment { rgb <1,0.5,0.2> } }
