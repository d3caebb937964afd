// Colour arithmetic: a float operand applies to all five channels; members read channels.
#declare C = rgb <0.2, 0.4, 0.6>;
#declare D = C * 0.5;
#declare E = C + 0.25;
sphere { 0, 1 pigment { D } }
sphere { x, 1 pigment { E } }
sphere { <C.red, C.green, C.blue>, C.gray }
