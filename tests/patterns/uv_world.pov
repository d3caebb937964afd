// uv_mapping where a shape has no uv of its own (plane, cylinder, cone, disc, CSG): the world
// hit's x and y; and uv_mapping in a texture, a texture_map and a normal.
#include "uv_common.inc"
plane { -z, -2 pigment { uv_mapping checker rgb 0.3, rgb 0.5 scale 0.5 } finish { UvFinish } }
cylinder { <-1.8, -1, 0>, <-1.2, 0.8, 0.3>, 0.4 pigment { UvPigment } finish { UvFinish } }
cone { <-0.5, -1.2, 0>, 0.5, <0, 0, 0>, 0.1 pigment { UvPigment } finish { UvFinish } rotate 15 * z }
union { box { <0.2, 0.2, 0>, <1, 1, 1> } cylinder { <0.6, 0.6, 0>, <0.6, 1.4, 0>, 0.3 }
  texture { uv_mapping pigment { UvColour } finish { UvFinish } scale 0.5 } rotate 10 * y }
sphere { <1.4, -0.6, 0>, 0.5
  texture { uv_mapping checker
    texture { pigment { rgb <1, 0.6, 0.2> } finish { UvFinish } }
    texture { pigment { rgb <0.2, 0.4, 1> } finish { UvFinish } }
    scale <0.125, 0.25, 1> } }
sphere { <-0.8, 1.1, 0>, 0.35 pigment { rgb 0.8 } finish { ambient 0.2 diffuse 0.8 }
  normal { uv_mapping bumps 1 scale 0.05 } }
light_source { <-5, 5, -10> rgb 1 }
