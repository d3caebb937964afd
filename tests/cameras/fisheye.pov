// fisheye: a circle of 200 degrees; outside it no ray (black)
#version 3.7;
camera { fisheye location <0,1,-3> look_at <0,1,0> angle 200 }
#include "scene.inc"
