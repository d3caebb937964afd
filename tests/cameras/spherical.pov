// spherical with both angles
#version 3.7;
camera { spherical location <0,1,-3> look_at <0,1,0> angle 200, 60 }
#include "scene.inc"
