// perspective with a camera normal; the gradient jumps at the image centre
#version 3.7;
camera { location <0,1,-3> look_at <0,1,0> normal { gradient x 1 } }
#include "scene.inc"
