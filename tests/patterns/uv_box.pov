// uv_mapping on boxes: the cross layout of the six faces, seen from the front and, turned,
// from behind and below; one box not at the origin and not a cube.
#include "uv_common.inc"
box { <-0.5, -0.5, -0.5>, <0.5, 0.5, 0.5> pigment { UvPigment } finish { UvFinish } rotate <30, 40, 0> translate <-1.2, 0.6, 0> }
box { <1, 0, -1>, <2.2, 0.8, 0.5> pigment { UvPigment } finish { UvFinish } translate <-1.6, -1.2, 0> rotate <-35, 200, 0> translate <1.2, -0.5, 0> }
box { <-0.4, -0.4, -0.4>, <0.4, 0.4, 0.4> uv_mapping pigment { UvColour } finish { UvFinish } rotate <-120, 15, 0> translate <1.4, 0.7, 0> }
