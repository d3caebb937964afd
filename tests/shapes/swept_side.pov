// Orthographic side view of prisms, a lathe and a sor: every ray is parallel to the caps
// (|D.y| = 0), so the caps are edge-on, the prism walls are met across the sweep and the lathe
// takes its across-the-axis branch (S.y(w) = P.y, then the circle's distances). Not a
// quadratic lathe: POV-Ray's closed-form quartic misses most of the double roots such rays
// give it (measured: bands of rows where a quadratic lathe is not hit), which lumen does not
// reproduce.
#include "swept_common.inc"
camera { orthographic location <0, 1, -10> look_at <0, 1, 0> right 8 * x up 6 * y }
prism { cubic_spline 0, 1.2, 7, <0, -0.6>, <0.6, 0>, <0, 0.6>, <-0.6, 0>, <0, -0.6>, <0.6, 0>, <0, 0.6>
  pigment { rgb <0.4, 0.5, 1> } rotate 30 * y translate <-2.8, 0, 0> }
prism { conic_sweep linear_spline 0.3, 1, 4, <-1, -1>, <1, -1>, <0, 1>, <-1, -1>
  pigment { rgb <0.3, 0.8, 0.4> } rotate 180 * x translate <-1.2, 1.8, 0> scale 1.3 }
lathe { linear_spline 6, <0, 0>, <0.5, 0>, <0.3, 0.5>, <0.5, 1>, <0.2, 1.4>, <0.3, 1.5>
  pigment { rgb <0.9, 0.4, 0.3> } scale 1.3 translate <0.6, 0, 0> }
lathe { bezier_spline 8, <0, 0>, <0.8, 0>, <0.6, 0.6>, <0.3, 0.8>, <0.3, 0.8>, <0.1, 1>, <0.5, 1.3>, <0, 1.4>
  pigment { rgb <0.9, 0.8, 0.3> } translate <2, 0.5, 1> }
sor { 7, <0, -0.1>, <0.3, 0>, <0.6, 0.4>, <0.3, 0.9>, <0.25, 1.1>, <0.4, 1.3>, <0.5, 1.5>
  pigment { rgb <0.8, 0.5, 0.9> } translate <3.2, 0, -0.5> }
