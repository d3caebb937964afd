// Focal blur: the near sphere in focus, the far one and the floor blurred. Samples (Declare
// S=...) pick POV's aperture grid: 4 (square), 7, 19, 37 (hexagonal), more (Halton points);
// Min sets blur_samples' minimum.
#version 3.7;
#ifndef (S) #declare S = 19; #end
#ifndef (Min) #declare Min = 1; #end
camera { location <0,1,-3> look_at <0,1,0> aperture 0.6 focal_point <-1.5,0.5,-1>
         blur_samples Min, S confidence 0.9 variance 1/256 }
#include "scene.inc"
