// A scene that renders in no time, for the start-up tests.
#version 3.7;
camera { location <0, 0, -3> look_at 0 }
light_source { <2, 4, -3> rgb 1 }
sphere { 0, 1 pigment { rgb <1, 0.5, 0.2> } }
