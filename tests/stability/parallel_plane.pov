// Stability: camera rays parallel to a plane. The camera sits in the plane y = 0 and looks
// along it; the middle row of the (odd-height) image runs exactly parallel to the plane, the
// rows below start on its surface. Expected: every ray that starts on the plane finds no hit
// at depth 0, so the whole image is the background, as in POV-Ray.
// expect: size 41x31
// expect: uniform 0 0 40 30 0.2 0.3 0.5 0
// expect: povray 45
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -5> look_at <0, 0, 0> }
background { rgb <0.2, 0.3, 0.5> }
light_source { <3, 10, -10> rgb 1 }
plane { y, 0 pigment { rgb <1, 0.8, 0.2> } finish { ambient 1 diffuse 0 } }
