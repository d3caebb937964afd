// uv_mapping on spheres: pigment level on a transformed sphere (the object's transforms do not
// move the uv pigment), object level with the pigment's own scale acting in uv space, and the
// poles (u undefined there).
#include "uv_common.inc"
sphere { <0.5, 0.2, 0>, 0.5 pigment { UvPigment } finish { UvFinish } scale 1.6 rotate <20, -30, 0> translate <-1.8, 0.1, 0> }
sphere { 0, 0.7 uv_mapping pigment { UvColour scale <0.5, 1, 1> } finish { UvFinish } rotate 60 * x translate <0.3, 0.5, 0> }
sphere { 0, 0.6 pigment { UvPigment } finish { UvFinish } rotate -90 * x translate <1.3, -0.8, 0> }
