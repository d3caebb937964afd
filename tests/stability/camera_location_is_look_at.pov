// Stability: a degenerate camera that looks at its own location (no view direction).
// Expected: lumen exits non-zero with a file:line:col error naming the problem, does not
// crash, and writes no image.
// expect: error 7:1 camera look_at equals its location
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <1, 2, 3> look_at <1, 2, 3> }
light_source { <3, 10, -10> rgb 1 }
sphere { 0, 1 pigment { rgb 1 } }
