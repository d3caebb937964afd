// density_file: POV-Ray's spiral.df3 (8-bit voxels, found on the include path) nearest and
// trilinear; a 5x4x3 16-bit grid (grid16.df3, beside this scene) nearest and trilinear, the
// unit cube stretched over each tile (outside it the density is 0).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
#declare F = finish { ambient 1 diffuse 0 }
#declare Ramp = color_map { [0 rgb <0.1, 0, 0.3>] [0.3 rgb <1, 0.3, 0>] [0.6 rgb <1, 1, 0.4>] [1 rgb <0.2, 0.6, 1>] }
box { <-2, 0, 0>, <0, 1.5, 1>
  pigment { density_file df3 "spiral.df3" color_map { Ramp } translate <0, 0, -0.5> scale <1.8, 1.4, 0.2> translate <-1.9, 0.05, 0> } finish { F } }
box { <0, 0, 0>, <2, 1.5, 1>
  pigment { density_file df3 "spiral.df3" interpolate 1 color_map { Ramp } translate <0, 0, -0.5> scale <1.8, 1.4, 0.2> translate <0.1, 0.05, 0> } finish { F } }
box { <-2, -1.5, 0>, <0, 0, 1>
  pigment { density_file df3 "grid16.df3" color_map { Ramp } translate <0, 0, -0.5> rotate 5 * z scale <1.8, 1.4, 1> translate <-1.9, -1.45, 0> } finish { F } }
box { <0, -1.5, 0>, <2, 0, 1>
  pigment { density_file df3 "grid16.df3" interpolate 1 color_map { Ramp } translate <0, 0, -0.5> rotate 5 * z scale <1.8, 1.4, 1> translate <0.1, -1.45, 0> } finish { F } }
