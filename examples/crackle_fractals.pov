// Crackle and fractal patterns, one per tile: crackle (default, form and metric 1, solid),
// cells, agate, marble with turbulence, mandel, julia with interior and exterior types,
// and magnet.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  orthographic
  location <0, 0, -10>
  look_at  <0, 0, 0>
  right x*6.6*image_width/image_height
  up y*6.6
}
light_source { <0, 0, -20> color rgb 1 }
background { color rgb 0.05 }
#default { finish { ambient 0.35 diffuse 0.65 } }

#declare Tile = box { <-1, -1, 0>, <1, 1, 0.1> }
#declare Warm = color_map { [0 rgb <0.1, 0.05, 0.2>] [0.3 rgb <0.8, 0.2, 0.1>] [0.6 rgb <1, 0.8, 0.2>] [1 rgb 1] }
#declare Cool = color_map { [0 rgb <0.02, 0.05, 0.15>] [0.5 rgb <0.1, 0.5, 0.8>] [1 rgb <0.9, 1, 1>] }

object { Tile pigment { crackle color_map { Warm } scale 0.35 } translate <-2.2, 2.2, 0> }
object { Tile pigment { crackle form <1, 0, 0> metric 1 color_map { Cool } scale 0.3 } translate <0, 2.2, 0> }
object { Tile pigment { crackle solid color_map { Warm } scale 0.3 } translate <2.2, 2.2, 0> }
object { Tile pigment { cells color_map { Cool } scale 0.25 } translate <-2.2, 0, 0> }
object { Tile pigment { agate agate_turb 0.6 color_map { Warm } scale 0.6 } translate <0, 0, 0> }
object { Tile pigment { marble turbulence 0.8 octaves 4 color_map { Cool } scale 0.5 } translate <2.2, 0, 0> }
object { Tile pigment { mandel 40 color_map { Warm } scale 0.7 translate <-0.3, 0, 0> } translate <-2.2, -2.2, 0> }
object { Tile pigment { julia <0.353, 0.288>, 30 interior 1, 1 exterior 2, 0.3 color_map { Cool } scale 0.8 } translate <0, -2.2, 0> }
object { Tile pigment { magnet 1 mandel 30 color_map { Warm } scale 0.4 translate <0.5, 0, 0> } translate <2.2, -2.2, 0> }
