#version 3.7; global_settings { assumed_gamma 1.0 }
camera { location <0,1,-5> look_at <0,0.5,0> }
light_source { <-4,6,-5> rgb 1 }
background { rgb <0.2,0.3,0.5> }
plane { y, -1 pigment { checker rgb 1 rgb <0.1,0.1,0.1> } }
sphere { <0,0,2>, 1 pigment { rgb <0.9,0.5,0.3> } }
fog { fog_type 2 distance 3 color rgbt <0.8,0.8,0.8,0.1> fog_offset -0.5 fog_alt 0.5 }
