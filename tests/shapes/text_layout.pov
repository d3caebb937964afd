// Layout: kerned pairs (AV, Wa, To in timrom.ttf kern), the first glyph moved to x = 0, a
// space, an offset that spreads the glyphs and one that makes them climb, a thin and a thick
// extrusion.
#include "text_common.inc"
text { ttf "timrom.ttf" "AVWa To" 0.3, 0
  pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.6 }
  translate <0, 1.2, 0> }
text { ttf "timrom.ttf" "AVWa" 0.05, <0.1, 0, 0>
  pigment { rgb <0.2, 0.7, 0.3> } scale 0.9 translate <0.1, 0.4, -0.5> }
text { ttf "timrom.ttf" "stairs" 1.2, <0, 0.08, 0.2>
  pigment { rgb <0.3, 0.5, 0.9> } scale 0.7 translate <2.6, -0.3, 0> }
