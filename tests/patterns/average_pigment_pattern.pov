// average: weighted pigments (weights 3 and 1); entries without a weight (1 each: only an
// entry that starts with a pattern may leave it out) that see the average's own warp and
// scale; pigment_pattern of a gradient pigment with a colour map, and of a pigment whose map
// entries are patterned.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
#declare F = finish { ambient 1 diffuse 0 }
#declare Ramp = color_map { [0 rgb <0.1, 0, 0.3>] [0.3 rgb <1, 0.3, 0>] [0.6 rgb <1, 1, 0.4>] [1 rgb <0.2, 0.6, 1>] }
box { <-2, 0, 0>, <0, 1.5, 1>
  pigment { average pigment_map {
    [3 gradient x color_map { [0 rgb <1, 0, 0>] [0.5 rgb <0, 0, 1>] [1 rgb <1, 0, 0>] } scale 0.7]
    [1 onion color_map { Ramp } scale 0.5 translate <-1, 0.7, 0>] } } finish { F } }
box { <0, 0, 0>, <2, 1.5, 1>
  pigment { average pigment_map {
    [gradient y color_map { [0 rgb <0, 1, 0>] [0.5 rgb <1, 0, 1>] [1 rgb <0, 1, 0>] }]
    [radial frequency 6 color_map { Ramp }]
    [2 rgb <0.2, 0.2, 0.8>] }
    warp { repeat x * 0.6 flip y } scale 0.8 translate <1, 0.7, 0> } finish { F } }
box { <-2, -1.5, 0>, <0, 0, 1>
  pigment { pigment_pattern { gradient x color_map { [0 rgb 0] [0.5 rgb <1, 0.6, 0.2>] [1 rgb 0] } rotate 30 * z }
    color_map { Ramp } scale 0.6 } finish { F } }
box { <0, -1.5, 0>, <2, 0, 1>
  pigment { pigment_pattern { checker pigment { onion color_map { Ramp } scale 0.3 } pigment { rgb <0.9, 0.9, 0.2> } scale 0.4 }
    frequency 2 color_map { Ramp } warp { black_hole <1, -0.75, 0>, 0.6 } } finish { F } }
