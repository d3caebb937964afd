// mandel: the default colour map; exponent 3 with exterior 2 (the escape point's x);
// exponent 5 (the generic power) with exterior 6 and interior 6 (POV-Ray's a² + b²·f);
// interior 1 (the orbit's least distance) with exterior 7 (the escape count modulo f).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
#declare F = finish { ambient 1 diffuse 0 }
#declare Ramp = color_map { [0 rgb <0.1, 0, 0.3>] [0.3 rgb <1, 0.3, 0>] [0.6 rgb <1, 1, 0.4>] [1 rgb <0.2, 0.6, 1>] }
box { <-2, 0, 0>, <0, 1.5, 1> pigment { mandel 30 scale 0.6 translate <-0.7, 0.75, 0> } finish { F } }
box { <0, 0, 0>, <2, 1.5, 1>
  pigment { mandel 40 exponent 3 exterior 2, 1 color_map { Ramp } scale 0.6 translate <1, 0.75, 0> } finish { F } }
box { <-2, -1.5, 0>, <0, 0, 1>
  pigment { mandel 25 exponent 5 exterior 6, 0.3 interior 6, 0.5 color_map { Ramp } scale 0.6 translate <-1, -0.75, 0> } finish { F } }
box { <0, -1.5, 0>, <2, 0, 1>
  pigment { mandel 50 interior 1, 1 exterior 7, 5 color_map { Ramp } scale 0.6 translate <1.3, -0.75, 0> } finish { F } }
