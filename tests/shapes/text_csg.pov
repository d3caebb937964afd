// Text in CSG: letters cut out of a slab (difference), a text clipped by a sphere
// (intersection), merged with a box, and a texture that moves with a turned text.
#include "text_common.inc"
difference {
  box { <-0.2, -0.2, 0> <2.2, 0.9, 0.3> }
  text { ttf "timrom.ttf" "CUT" 0.6, 0 scale 0.9 translate <0.1, 0, -0.1> }
  pigment { rgb <0.9, 0.6, 0.3> }
  rotate <0, -20, 0> translate <0, 0.8, 0>
}
intersection {
  text { ttf "cyrvetic.ttf" "Q@" 1, 0 scale 1.2 }
  sphere { <0.7, 0.5, 0.5>, 0.75 }
  pigment { rgb <0.3, 0.8, 0.5> }
  translate <2.3, -0.2, -0.4>
}
merge {
  text { ttf "timrom.ttf" "M" 0.4, 0 }
  box { <0, -0.05, 0.1> <1, 0.05, 0.3> }
  pigment { rgb <0.5, 0.5, 1> }
  translate <3.6, 1.1, 0>
}
text { ttf "timrom.ttf" "tex" 0.3, <0.05, 0, 0>
  pigment { gradient x color_map { [0 rgb <1, 0.2, 0.2>] [1 rgb <0.2, 0.2, 1>] } scale 0.4 }
  rotate <0, 30, 0> translate <0.6, -0.3, -1.2> }
