// polynomial { Order, xyz(i, j, k): c ... } (POV-Ray 3.7's named-term form): the torus quartic
// of algebraic_poly.pov by its terms (commas optional, a term written twice takes the later
// value), a sextic with sturm, and a superellipsoid with e = 0 (an infinite power).
#include "algebraic_common.inc"
polynomial { 4,
  xyz(4, 0, 0): 1, xyz(0, 4, 0): 1, xyz(0, 0, 4): 1,
  xyz(2, 2, 0): 2, xyz(2, 0, 2): 2, xyz(0, 2, 2): 2,
  xyz(2, 0, 0): 5  xyz(2, 0, 0): -2.32  xyz(0, 2, 0): 1.68, xyz(0, 0, 2): -2.32,
  xyz(0, 0, 0): 0.7056
  pigment { rgb <1, 0.5, 0.3> } rotate <60, 20, 0> translate <-2.2, 0.2, 0> }
polynomial { 6 xyz(6, 0, 0): 1 xyz(0, 6, 0): 1 xyz(0, 0, 6): 1 xyz(0, 0, 0): -0.4 sturm
  pigment { rgb <0.4, 0.8, 0.4> } rotate <0, 30, 0> translate <0, 0, 0> }
superellipsoid { <0, 0.6> pigment { rgb <1, 0.9, 0.4> } rotate <-20, 40, 0> scale 0.6 translate <0.5, -0.7, -2.5> }
