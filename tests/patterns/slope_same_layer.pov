// A slope pigment in the same layer as a normal: POV-Ray perturbs a layer's normal before it
// evaluates that layer's pigment, so the slope sees the bumps of its own layer. Declare
// Layers=2 puts a second, bumpy slope layer over the first (each layer its own normal).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -4> look_at 0 angle 40 }
light_source { <200, 200, -200>, color rgb 1.2 }
#ifndef (Layers) #declare Layers = 1; #end
sphere { 0, 1
  texture {
    pigment { slope { y, 0.2, 0.9 } color_map { [0 rgb <0.8, 0.2, 0.1>] [0.5 rgb <0.9, 0.9, 0.2>] [1 rgb <0.1, 0.3, 0.9>] } }
    normal { bumps 0.7 scale 0.08 }
    finish { ambient 0.1 diffuse 0.8 }
  }
  #if (Layers > 1)
  texture {
    pigment { aoi color_map { [0 rgbt <1, 1, 1, 1>] [0.6 rgbt <0.2, 0.8, 0.2, 0.3>] [1 rgbt <0, 0, 0, 1>] } }
    normal { wrinkles 0.9 scale 0.15 }
    finish { ambient 0.1 diffuse 0.6 }
  }
  #end
}
