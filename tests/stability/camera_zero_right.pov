// Stability: a degenerate camera with a zero-length right vector (every column would
// be the same ray).
// Expected: lumen exits non-zero with a file:line:col error naming the problem, does not
// crash, and writes no image.
// expect: error 8:30 camera right is a zero vector
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -5> right <0, 0, 0> }
light_source { <3, 10, -10> rgb 1 }
sphere { 0, 1 pigment { rgb 1 } }
