// Stability: a degenerate camera with a zero-length direction.
// Expected: lumen exits non-zero with a file:line:col error naming the problem, does not
// crash, and writes no image.
// expect: error 7:30 camera direction is a zero vector
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -5> direction <0, 0, 0> }
light_source { <3, 10, -10> rgb 1 }
sphere { 0, 1 pigment { rgb 1 } }
