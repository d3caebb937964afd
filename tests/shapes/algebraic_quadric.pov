// quadric: an ellipsoid with mixed terms, a hyperboloid of one sheet clipped by a box and
// turned (the transform folded into the coefficients), a paraboloid (no quadratic term along
// rays parallel to its axis) and a cone cut by a plane in an intersection.
#include "algebraic_common.inc"
quadric { <1, 2, 1.5>, <0.3, 0, 0.2>, <0.1, 0, 0>, -0.8
  pigment { rgb <1, 0.5, 0.3> } translate <-2.3, 0, 0> }
quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, -0.2
  clipped_by { box { -1, 1 } }
  pigment { rgb <0.4, 0.8, 0.4> } rotate <30, 0, 20> scale <0.8, 1, 0.8> translate <0, 0, 0.5> }
quadric { <1, 0, 1>, <0, 0, 0>, <0, -1, 0>, 0
  clipped_by { plane { y, 1.2 } }
  pigment { rgb <0.4, 0.6, 1> } scale 0.7 translate <2.2, -0.8, 0> }
intersection {
  quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, 0 }
  plane { y, 0 } plane { -y, 0.9 }
  pigment { rgb <1, 0.9, 0.4> } translate <0, 0.9, -2.5> }
