// prism silhouettes in orthographic views: from straight above (the caps' in-curve test alone)
// and along the sweep from the side (walls edge on), with the rays parallel to the sweep.
#include "swept_common.inc"
camera { orthographic location <0, 10, 0> look_at 0 right 6 * x up 4.5 * z }
prism { cubic_spline 0, 1, 8,
  <0, -1>, <1, 0>, <0.3, 0.9>, <-1, 0.2>, <-0.5, -0.8>, <0, -1>, <1, 0>, <0.3, 0.9>
  pigment { rgb <0.4, 0.5, 1> } translate <-1.5, 0, 0.8> }
prism { quadratic_spline 0, 1, 7,
  <-1, 0>, <0, -1>, <1, -0.2>, <0.6, 0.8>, <-0.2, 0.5>, <-1, 0.4>, <0, -1>
  pigment { rgb <0.3, 0.8, 0.4> } translate <1.3, 0, 0.9> }
prism { linear_spline -1, 1, 5, <0, 0>, <1, 0>, <1, 0.5>, <0.5, 0.25>, <0, 0.5>
  pigment { rgb <0.9, 0.4, 0.3> } translate <-2.3, 0, -1.5> }
prism { bezier_spline 0, 0.5, 8,
  <1, 0>, <1, 1.2>, <-1, 1.2>, <-1, 0>, <-1, 0>, <-1, -0.6>, <1, -0.6>, <1, 0>
  pigment { rgb <0.9, 0.8, 0.3> } scale 0.6 translate <1.2, 0, -1.3> }
