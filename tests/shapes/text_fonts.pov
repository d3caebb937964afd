// The four fonts POV-Ray installs, glyphs with holes (O, B, 8, e), turned so that the walls
// show, and a text seen edge-on along its extrusion.
#include "text_common.inc"
text { ttf "cyrvetic.ttf" "OB8e" 0.4, 0 pigment { rgb <1, 0.8, 0.2> }
  rotate <0, -25, 0> translate <-0.2, 0.9, 0.3> }
text { ttf "crystal.ttf" "Glass" 0.25, 0 pigment { rgb <0.6, 0.9, 1> } finish { specular 0.5 }
  scale 0.8 rotate <20, 15, 0> translate <1.5, -0.2, -0.6> }
text { ttf "povlogo.ttf" "P" 0.5, 0 pigment { rgb <0.8, 0.2, 0.9> }
  scale 1.3 rotate <0, 70, 0> translate <3.6, 0, 0> }
text { ttf "timrom.ttf" "Rg%&" 0.5, 0 pigment { rgb 0.9 } finish { reflection 0.2 }
  scale 0.6 rotate <-10, 0, 5> translate <2.2, 1.3, 1> }
