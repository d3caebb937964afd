// sor: a capped vase, an open one (the inside shows), one in a difference (inside decides)
// and one lying on its side, where rays run along the axis.
#include "swept_common.inc"
camera { location <1, 3.5, -6> look_at <1, 0.5, 0> angle 50 }
#declare Vase = sor { 7, <0, -0.1>, <0.3, 0>, <0.6, 0.4>, <0.3, 0.9>, <0.25, 1.1>, <0.4, 1.3>, <0.5, 1.5> }
object { Vase pigment { rgb <0.9, 0.4, 0.3> } translate <-1.2, 0, 0> }
sor { 7, <0, -0.1>, <0.3, 0>, <0.6, 0.4>, <0.3, 0.9>, <0.25, 1.1>, <0.4, 1.3>, <0.5, 1.5> open
  pigment { rgb <0.3, 0.8, 0.4> } translate <0.2, 0, 0> }
difference { object { Vase } box { <-1, 0.6, -1>, <0, 2, 0> }
  pigment { rgb <0.4, 0.5, 1> } rotate -30 * y translate <1.6, 0, 0> }
sor { 5, <0, 0>, <0.3, 0.2>, <0.5, 0.6>, <0.2, 1.2>, <0.1, 1.5>
  pigment { rgb <0.9, 0.8, 0.3> } rotate -90 * z translate <2.8, 0.5, -1.4> }
