// A declared orthographic camera used again arrives sized: the copy renders as the original.
#version 3.7;
#declare C = camera { orthographic angle 15 location <20, 20, -20> right x*4/3 look_at <0, 0.5, 0> }
camera { C }
#include "scene.inc"
