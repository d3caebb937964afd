// Constant fog with turbulence: the fog is thinned by the turbulence at each segment's
// midpoint, less so for longer segments.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -6> look_at <0, 0.5, 0> }
plane { y, -1 pigment { checker rgb <0.2, 0.3, 0.5> rgb <0.8, 0.7, 0.4> } finish { ambient 1 diffuse 0 } }
sphere { <0.5, 0.3, 2>, 1 pigment { rgb <0.9, 0.2, 0.1> } finish { ambient 1 diffuse 0 } }
fog { distance 6 color rgbt <0.8, 0.85, 0.9, 0.1> turbulence <0.6, 0.3, 0.5> turb_depth 0.4
      octaves 4 omega 0.6 lambda 2.3 }
