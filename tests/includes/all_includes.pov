// Every standard include lumen must read (tests/includes): `lumen --check` must exit 0.
#version 3.7;
#include "colors.inc"
#include "textures.inc"
#include "metals.inc"
#include "glass.inc"
#include "woods.inc"
#include "stones.inc"
#include "golds.inc"
#include "finish.inc"
#include "shapes.inc"
#include "math.inc"
#include "transforms.inc"
#include "consts.inc"
#include "functions.inc"
#include "strings.inc"
#include "skies.inc"

camera { location <0, 1, -4> look_at <0, 0.5, 0> }
light_source { <5, 10, -5> color White }
sphere { <0, 0.5, 0>, 0.5 pigment { color Red } finish { phong 0.5 } }
