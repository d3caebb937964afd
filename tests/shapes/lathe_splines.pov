// lathe: the four spline kinds, a linear cup open at the top, a quadratic vase, a cubic closed
// ring (clear of the axis) and a Bezier bulb; seen in perspective from above, so the inside of
// the open ones shows.
#include "swept_common.inc"
camera { location <1.5, 4, -6> look_at <1.5, 0.5, 0> angle 50 }
lathe { linear_spline 5, <0, 0>, <0.5, 0>, <0.6, 0.8>, <0.55, 0.8>, <0.45, 0.05>
  pigment { rgb <0.9, 0.4, 0.3> } translate <-1.2, 0, 0> }
lathe { quadratic_spline 6, <0, 0>, <0.5, 0>, <0.3, 0.5>, <0.5, 1>, <0.2, 1.4>, <0.3, 1.5>
  pigment { rgb <0.3, 0.8, 0.4> } translate <0.4, 0, 0> }
lathe { cubic_spline 7, <0.2, 0.6>, <0.3, 0.1>, <0.7, 0.2>, <0.6, 0.7>, <0.2, 0.6>, <0.3, 0.1>, <0.7, 0.2>
  pigment { rgb <0.4, 0.5, 1> } rotate 20 * x translate <2, 0.1, 0> }
lathe { bezier_spline 8, <0, 0>, <0.8, 0>, <0.6, 0.6>, <0.3, 0.8>, <0.3, 0.8>, <0.1, 1>, <0.5, 1.3>, <0, 1.4>
  pigment { rgb <0.9, 0.8, 0.3> } translate <3.6, 0, 0> }
