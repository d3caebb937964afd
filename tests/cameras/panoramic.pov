// panoramic: the angle is ignored; the poles clamp tan to 1e10
#version 3.7;
camera { panoramic location <0,1,-3> look_at <0,1,0> angle 30 }
#include "scene.inc"
