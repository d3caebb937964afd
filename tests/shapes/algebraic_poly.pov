// poly, cubic and quartic (POV-Ray's solver rules): a torus quartic, the same one with sturm
// and turned, a cubic saddle clipped by a box, an order-6 poly (always the Sturm search).
#include "algebraic_common.inc"
// (x^2 + y^2 + z^2 + 0.84)^2 - 4 (x^2 + z^2): a torus R 1, r 0.4.
#declare Torus4 = quartic {
  < 1, 0, 0, 0, 2, 0, 0, 2, 0, -2.32,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    1, 0, 0, 2, 0, 1.68, 0, 0, 0, 0,
    1, 0, -2.32, 0, 0.7056 >
}
object { Torus4 pigment { rgb <1, 0.5, 0.3> } translate <-2.2, 0, 0> }
object { Torus4 sturm pigment { rgb <0.4, 0.8, 0.4> } rotate <70, 20, 0> translate <0.3, 0.4, 0> }
// x^3 - 3 x y^2 - z = 0, a monkey saddle, within a box.
cubic {
  < 1, 0, 0, 0, -3, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, -1, 0 >
  clipped_by { box { -0.9, 0.9 } }
  pigment { rgb <0.4, 0.6, 1> }
  rotate <-90, 0, 0> translate <2.4, 0.2, 0>
}
// x^6 + y^6 + z^6 - 0.4 = 0: a rounded cube through the Sturm search.
poly { 6, <
    1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, -0.4 >
  pigment { rgb <1, 0.9, 0.4> } scale 0.9 translate <0, -0.6, -2> }
