// Stability: a degenerate camera whose up vector is parallel to its direction (the
// image rows would run along the view direction).
// Expected: lumen exits non-zero with a file:line:col error naming the problem, does not
// crash, and writes no image.
// expect: error 8:42 camera up is parallel to the camera direction
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -5> direction z up z right x }
light_source { <3, 10, -10> rgb 1 }
sphere { 0, 1 pigment { rgb 1 } }
