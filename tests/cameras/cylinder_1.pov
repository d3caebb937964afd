// cylinder 1, stretched vectors (|up| 2, |right| 1.5) and a camera normal
#version 3.7;
camera { cylinder 1 location <0,1,-3> look_at <0,1,0> up 2*y right 1.5*x angle 120 normal { bumps 0.3 } }
#include "scene.inc"
