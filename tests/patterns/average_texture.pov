// average texture_map: each entry shaded with its own finish and the results weighted
// (weights 3 and 1, and entries without a weight); an average as an entry of a checker
// texture.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
light_source { <-5, 8, -10> rgb 1 }
#declare Ramp = color_map { [0 rgb <0.1, 0, 0.3>] [0.3 rgb <1, 0.3, 0>] [0.6 rgb <1, 1, 0.4>] [1 rgb <0.2, 0.6, 1>] }
sphere { <-1, 0.75, 0>, 0.7
  texture { average texture_map {
    [3 pigment { gradient y color_map { Ramp } scale 0.5 } finish { ambient 0.2 diffuse 0.8 phong 0.9 }]
    [1 pigment { rgb <0.2, 0.9, 0.3> } finish { ambient 1 diffuse 0 }] } } }
sphere { <1, 0.75, 0>, 0.7
  texture { average texture_map {
    [pigment { onion scale 0.3 color_map { Ramp } } finish { ambient 0.1 diffuse 0.9 }]
    [pigment { gradient x color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] } } finish { ambient 0.6 diffuse 0.3 specular 0.6 }] }
    translate <1, 0.75, 0> } }
box { <-2, -1.5, 0>, <2, 0, 1>
  texture { checker
    texture { average texture_map {
      [1 pigment { checker rgb <1, 0.8, 0.2> rgb <0.1, 0.3, 0.8> scale 0.2 } finish { ambient 0.3 diffuse 0.7 }]
      [2 pigment { radial frequency 8 color_map { Ramp } rotate 90 * x } finish { ambient 0.8 diffuse 0.2 }] } }
    texture { pigment { rgb <0.9, 0.9, 0.9> } finish { ambient 0.2 diffuse 0.8 } }
    scale 0.75 } }
