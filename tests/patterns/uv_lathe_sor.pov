// uv_mapping on lathes (linear and cubic splines: v is the segment plus the spline parameter)
// and sors (sides, base and cap discs), tilted to show the ends.
#include "uv_common.inc"
lathe { linear_spline 4, <0.2, -0.8>, <0.7, -0.3>, <0.4, 0.4>, <0.6, 0.8>
  pigment { UvPigment } finish { UvFinish } rotate -25 * x translate <-1.5, 0.6, 0> }
lathe { cubic_spline 6, <0, -1>, <0.3, -0.8>, <0.6, -0.2>, <0.3, 0.3>, <0.5, 0.8>, <0, 1>
  uv_mapping pigment { UvColour } finish { UvFinish } rotate <30, 40, 0> translate <-0.2, 0.3, 0> }
sor { 6, <0, -0.9>, <0.5, -0.7>, <0.7, -0.2>, <0.4, 0.3>, <0.6, 0.7>, <0.3, 0.9>
  pigment { UvPigment } finish { UvFinish } rotate -50 * x translate <1.2, 0.6, 0> }
sor { 5, <0.2, -0.9>, <0.6, -0.6>, <0.3, 0>, <0.5, 0.6>, <0.4, 0.8>
  pigment { UvPigment } finish { UvFinish } rotate 50 * x translate <0.6, -0.9, 0> }
