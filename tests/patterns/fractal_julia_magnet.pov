// julia (exterior 1: the escape count over the iterations) and julia exponent 4 with
// interior 2; magnet 1 mandel with exterior 1 and interior 1; magnet 2 julia with exterior 8
// and interior 3.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
#declare F = finish { ambient 1 diffuse 0 }
#declare Ramp = color_map { [0 rgb <0.1, 0, 0.3>] [0.3 rgb <1, 0.3, 0>] [0.6 rgb <1, 1, 0.4>] [1 rgb <0.2, 0.6, 1>] }
box { <-2, 0, 0>, <0, 1.5, 1>
  pigment { julia <0.353, 0.288>, 30 color_map { Ramp } scale 0.6 translate <-1, 0.75, 0> } finish { F } }
box { <0, 0, 0>, <2, 1.5, 1>
  pigment { julia <-0.5, 0.4>, 20 exponent 4 interior 2, 0.8 color_map { Ramp } scale 0.6 translate <1, 0.75, 0> } finish { F } }
box { <-2, -1.5, 0>, <0, 0, 1>
  pigment { magnet 1 mandel 20 interior 1, 0.3 color_map { Ramp } scale 0.5 translate <-1.6, -0.75, 0> } finish { F } }
box { <0, -1.5, 0>, <2, 0, 1>
  pigment { magnet 2 julia <0.3, 0.2>, 25 exterior 8, 3 interior 3, 1 color_map { Ramp } scale 0.35 translate <0.6, -0.75, 0> } finish { F } }
