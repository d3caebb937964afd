// prisms in CSG: inside (half-open heights, even-odd holes) decides what a difference and an
// intersection keep; a sphere cut by a star prism, a box with a prism-shaped hole, and a
// conic prism intersected with a box.
#include "swept_common.inc"
camera { location <1, 4, -5.5> look_at <1, 0.3, 0> angle 50 }
#declare Star = prism { linear_spline -1, 1, 11,
  <0, 1>, <0.22, 0.3>, <0.95, 0.31>, <0.36, -0.12>, <0.59, -0.81>, <0, -0.38>,
  <-0.59, -0.81>, <-0.36, -0.12>, <-0.95, 0.31>, <-0.22, 0.3>, <0, 1> }
intersection { sphere { 0, 0.8 } object { Star scale <0.9, 0.5, 0.9> }
  pigment { rgb <0.9, 0.6, 0.3> } translate <-1, 0.6, 0> }
difference { box { <-0.7, 0, -0.7>, <0.7, 0.5, 0.7> }
  prism { cubic_spline -0.1, 0.6, 7,
    <0, -0.4>, <0.4, 0>, <0, 0.4>, <-0.4, 0>, <0, -0.4>, <0.4, 0>, <0, 0.4> }
  pigment { rgb <0.4, 0.6, 1> } rotate 20 * y translate <1.2, 0, 0> }
intersection { prism { conic_sweep linear_spline 0, 1, 5, <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1> }
  box { <-1, 0.3, -1>, <1, 0.9, 1> }
  pigment { rgb <0.4, 0.9, 0.5> } rotate 180 * x translate <3, 1, 0.3> }
