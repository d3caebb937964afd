// Text, for the start-up tests: FreeType is opened for it.
#version 3.7;
camera { location <0.5, 0.4, -2> look_at <0.5, 0.4, 0> }
light_source { <2, 4, -3> rgb 1 }
text { ttf "timrom.ttf" "A" 0.2, 0 pigment { rgb 1 } }
