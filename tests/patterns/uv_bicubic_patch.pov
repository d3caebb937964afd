// uv_mapping on bicubic patches: the default corner uvs and given uv_vectors, on a curved patch.
#include "uv_common.inc"
#declare Net = array[16] {
  <0, 0, 0>, <1, 0, 0.5>, <2, 0, 0.5>, <3, 0, 0>,
  <0, 1, 0.5>, <1, 1, 1.5>, <2, 1, 1.5>, <3, 1, 0.5>,
  <0, 2, 0.5>, <1, 2, 1.5>, <2, 2, 1.5>, <3, 2, 0.5>,
  <0, 3, 0>, <1, 3, 0.5>, <2, 3, 0.5>, <3, 3, 0> }
bicubic_patch { type 1 u_steps 3 v_steps 3
  Net[0], Net[1], Net[2], Net[3], Net[4], Net[5], Net[6], Net[7],
  Net[8], Net[9], Net[10], Net[11], Net[12], Net[13], Net[14], Net[15]
  pigment { UvPigment } finish { UvFinish } scale 0.55 rotate <-20, 10, 0> translate <-1.9, -0.8, 0> }
bicubic_patch { type 0 u_steps 2 v_steps 3 uv_vectors <0.2, 0>, <1, 0.1>, <0.8, 0.9>, <0, 1>
  Net[0], Net[1], Net[2], Net[3], Net[4], Net[5], Net[6], Net[7],
  Net[8], Net[9], Net[10], Net[11], Net[12], Net[13], Net[14], Net[15]
  uv_mapping pigment { UvColour } finish { UvFinish } scale 0.55 rotate <10, 160, 0> translate <1.8, -0.8, 0> }
