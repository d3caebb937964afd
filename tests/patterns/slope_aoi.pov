// slope and aoi on spheres seen by an orthographic camera: slope y; slope with a range and
// an altitude with its own range; slope point_at; aoi. The normal faces the ray, so the
// inside of the clipped sphere shows it too.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
#declare F = finish { ambient 1 diffuse 0 }
#declare Ramp = color_map { [0 rgb <0.1, 0, 0.3>] [0.3 rgb <1, 0.3, 0>] [0.6 rgb <1, 1, 0.4>] [1 rgb <0.2, 0.6, 1>] }
sphere { <-1, 0.75, 0>, 0.7 pigment { slope y color_map { Ramp } } finish { F } }
sphere { <1, 0.75, 0>, 0.7 pigment { slope { <0, 2, -1>, 0.2, 0.9 altitude y, 0.3, 1.2 } color_map { Ramp } } finish { F } }
sphere { <-1, -0.75, 0>, 0.7 pigment { slope { point_at <-3, 2, -2> } color_map { Ramp } rotate 30 * z } finish { F } }
sphere { <1, -0.75, 0>, 0.7 pigment { aoi color_map { Ramp } } finish { F }
  clipped_by { plane { -z, -0.2 } } }
