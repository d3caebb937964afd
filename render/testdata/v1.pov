#version 3.7; global_settings { assumed_gamma 1.0 }
camera { location <0,0,-5> }
light_source { <0,0,-100> rgb 1 }
sphere { 0, 1 pigment { rgb 1 } }
