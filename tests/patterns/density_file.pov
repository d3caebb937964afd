// density_file: POV-Ray's spiral.df3 (8-bit voxels, found on the include path) and a 5x4x3
// 16-bit grid (grid16.df3, beside this scene), each nearest, trilinear and tricubic (whose
// undershoot beside spiral's sharp edges POV-Ray holds at 0), the unit cube stretched over
// each tile (outside it the density is 0).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
#declare F = finish { ambient 1 diffuse 0 }
#declare Ramp = color_map { [0 rgb <0.1, 0, 0.3>] [0.3 rgb <1, 0.3, 0>] [0.6 rgb <1, 1, 0.4>] [1 rgb <0.2, 0.6, 1>] }
#macro Spiral(Interpolate, X)
  box { <X, 0, 0>, <X + 4/3, 1.5, 1>
    pigment { density_file df3 "spiral.df3" interpolate Interpolate color_map { Ramp }
      translate <0, 0, -0.5> scale <1.25, 1.4, 0.2> translate <X + 0.04, 0.05, 0> } finish { F } }
#end
#macro Grid(Interpolate, X)
  box { <X, -1.5, 0>, <X + 4/3, 0, 1>
    pigment { density_file df3 "grid16.df3" interpolate Interpolate color_map { Ramp }
      translate <0, 0, -0.5> rotate 5 * z scale <1.23, 1.37, 1> translate <X + 0.05, -1.44, 0> } finish { F } }
#end
Spiral(0, -2) Spiral(1, -2/3) Spiral(2, 2/3)
Grid(0, -2) Grid(1, -2/3) Grid(2, 2/3)
