#version 3.7; global_settings { assumed_gamma 1.0 }
camera { location <0,1,-5> look_at <0,0.5,0> }
light_source { <-4,6,-5> rgb 1 }
background { rgb <0.2,0.3,0.5> }
plane { y, -1 pigment { checker rgb 1 rgb <0.1,0.1,0.1> } }
sphere { <-1,0,0>, 1 pigment { rgb <0.9,0.7,0.3> } finish { reflection { 0.1, 0.9 falloff 2 } } }
sphere { <1.2,0,0.5>, 1 pigment { rgb <0.3,0.6,0.9> } finish { reflection { 0.5 metallic } phong 0.5 } }
