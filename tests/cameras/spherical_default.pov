// spherical with its defaults (360 by 180) and a camera normal
#version 3.7;
camera { spherical location <0,1,-3> look_at <0,1,0> normal { gradient x 1 } }
#include "scene.inc"
