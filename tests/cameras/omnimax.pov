// omnimax on a wide image, with a camera normal (evaluated at phi, theta)
#version 3.7;
camera { omnimax location <0,1,-3> look_at <0,1,0> right 1.6*x normal { bumps 0.3 scale 0.05 } }
#include "scene.inc"
