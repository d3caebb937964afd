// uv_mapping on tori: around the ring and around the tube, one tilted to show both.
#include "uv_common.inc"
torus { 0.8, 0.3 pigment { UvPigment } finish { UvFinish } rotate -60 * x translate <-0.9, 0.3, 0> }
torus { 0.5, 0.25 uv_mapping pigment { UvColour } finish { UvFinish } rotate <20, 30, 70> translate <1.2, -0.5, 0> }
