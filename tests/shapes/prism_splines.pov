// prism: the four spline kinds side by side (linear with a hole, quadratic, Catmull-Rom cubic
// with a hole, Bezier of two sub-shapes), seen from the front and above in perspective, so
// that caps, walls and silhouettes all show.
#include "swept_common.inc"
camera { location <1.5, 4.5, -6.5> look_at <1.5, 0.3, 0> angle 50 }
prism { linear_spline 0, 0.6, 10,
  <-0.5, -0.5>, <0.5, -0.5>, <0.5, 0.5>, <-0.5, 0.5>, <-0.5, -0.5>,
  <-0.2, -0.2>, <0.2, -0.2>, <0.2, 0.2>, <-0.2, 0.2>, <-0.2, -0.2>
  pigment { rgb <0.9, 0.4, 0.3> } translate <-1.2, 0, 0.8> }
prism { quadratic_spline 0, 0.8, 6,
  <-0.5, 0>, <0, -0.5>, <0.6, 0>, <0, 0.6>, <-0.6, 0>, <0, -0.5>
  pigment { rgb <0.3, 0.8, 0.4> } translate <0.4, 0, 0.8> }
prism { cubic_spline -0.2, 0.5, 14,
  <0, -0.6>, <0.6, 0>, <0, 0.6>, <-0.6, 0>, <0, -0.6>, <0.6, 0>, <0, 0.6>,
  <0, -0.25>, <0.25, 0>, <0, 0.25>, <-0.25, 0>, <0, -0.25>, <0.25, 0>, <0, 0.25>
  pigment { rgb <0.4, 0.5, 1> } translate <2.0, 0, 0.8> }
prism { bezier_spline 0, 1, 16,
  <0.5, 0>, <0.5, 0.4>, <-0.5, 0.4>, <-0.5, 0>,
  <-0.5, 0>, <-0.5, -0.4>, <0.5, -0.4>, <0.5, 0>,
  <0.2, 0>, <0.2, 0.1>, <-0.2, 0.1>, <-0.2, 0>,
  <-0.2, 0>, <-0.2, -0.1>, <0.2, -0.1>, <0.2, 0>
  pigment { rgb <0.9, 0.8, 0.3> } rotate <0, 30, 0> translate <3.6, 0, 0.8> }
prism { linear_spline 0.2, 1.2, 3, <0, 0>, <0.8, 0>, <0.4, 0.7>
  pigment { rgb <0.8, 0.5, 0.9> } rotate <-90, 0, 0> translate <0.9, 0.2, -1.2> }
