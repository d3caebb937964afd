// Stability: a closed mirror box around the camera, so every ray reflects until it reaches
// max_trace_level (60 here). Each surface has ambient 0.01, no diffuse and reflection 1, and
// the reflection keeps the ray weight at 1, so each of the 60 trace levels adds exactly 0.01:
// Expected: every pixel is 0.6 (linear) in each channel, as in POV-Ray. (A ray meeting a
// face within 1e-4 of an edge would skip the next face, closer than the minimum depth, and
// escape: the view is chosen so that none of the 60 bounces of any pixel comes that close.)
// expect: size 32x24
// expect: uniform 0 0 31 23 0.6 0.6 0.6 1e-5
// expect: povray 45
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 60 }
camera { location <0.05, 0.1, 0.2> look_at <2, 1.1, 3.3> }
light_source { <0, 0, 0> rgb 1 }
box { -2, 2
  pigment { rgb 1 }
  finish { ambient 0.01 diffuse 0 reflection 1 }
}
