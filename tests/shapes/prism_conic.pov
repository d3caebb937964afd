// conic_sweep prisms: a frustum of a square (heights 0.4 to 1), an open one (no caps: the
// inside walls show), a cubic outline, and one set on its side; linear_sweep for contrast.
#include "swept_common.inc"
camera { location <1, 3.5, -6> look_at <1, 0.4, 0> angle 48 }
prism { conic_sweep linear_spline 0.4, 1, 5, <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>
  pigment { rgb <0.9, 0.4, 0.3> } rotate 180 * x translate <-1, 1, 0> scale 0.7 }
prism { conic_sweep linear_spline 0.3, 1, 4, <-1, -1>, <1, -1>, <0, 1>, <-1, -1> open
  pigment { rgb <0.3, 0.8, 0.4> } rotate 180 * x translate <0.8, 1, 0> }
prism { conic_sweep cubic_spline 0.2, 1, 7,
  <0, -1>, <1, 0>, <0, 1>, <-1, 0>, <0, -1>, <1, 0>, <0, 1>
  pigment { rgb <0.4, 0.5, 1> } scale <0.6, 1, 0.6> translate <2.6, 0, 0.3> }
prism { conic_sweep linear_spline 0, 1, 4, <-0.5, -0.5>, <0.5, -0.5>, <0, 0.5>, <-0.5, -0.5>
  pigment { rgb <0.9, 0.8, 0.3> } rotate 90 * z translate <1, 0.5, -1.6> }
