// Stability: camera rays parallel to a plane. The camera is 1 unit above the plane y = 0 and
// looks horizontally; the middle row of the (odd-height) image runs exactly parallel to the
// plane (ray.dir.y = 0). Expected: that row and all rows above it are the background, every
// row below it is the plane's flat colour (ambient only), exactly as in POV-Ray.
// expect: size 41x31
// expect: uniform 0 0 40 15 0.2 0.3 0.5 0
// expect: uniform 0 16 40 30 1 0.8 0.2 0
// expect: povray 45
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -5> look_at <0, 1, 0> }
background { rgb <0.2, 0.3, 0.5> }
light_source { <3, 10, -10> rgb 1 }
plane { y, 0 pigment { rgb <1, 0.8, 0.2> } finish { ambient 1 diffuse 0 } }
