// ultra_wide_angle 150 degrees, with a camera normal (evaluated at the angles)
#version 3.7;
camera { ultra_wide_angle location <0,1,-3> look_at <0,1,0> angle 150 normal { bumps 0.3 scale 0.05 } }
#include "scene.inc"
