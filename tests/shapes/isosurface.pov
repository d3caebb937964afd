// isosurface (render/shapes/isosurface.cpp) against POV-Ray: box and sphere containers that
// cut the solid (closed: a flat cut face; open: hollow), threshold, internal and noise
// functions, a pigment function and a pattern function, transforms; Variant 1: max_trace 2
// and all_intersections through glass and in CSG, evaluate; Variant 2: max_gradient far too
// low on a noise sphere, rendered on one thread: the holes then depend on POV-Ray's cross-ray
// cache of failed searches, so on pixel order (lumen: identical; without the cache 2.8% of
// the pixels differ).
#version 3.7;
#include "functions.inc"
#ifndef (Variant) #declare Variant = 0; #end
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 0.3, 0> angle 50 }
light_source { <-5, 10, -8> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
plane { y, -1.2 pigment { checker rgb 0.8 rgb 0.5 } }
#declare Stone = function { pigment { granite scale 0.6 colour_map { [0 rgb 0.2] [1 rgb 1] } } }
#declare Bands = function { pattern { gradient y frequency 3 triangle_wave } }
#if (Variant = 2)
  isosurface { function { f_sphere(x, y, z, 1) - f_noise3d(x * 4, y * 4, z * 4) * 0.6 }
    contained_by { sphere { 0, 1.8 } } max_gradient 0.5
    pigment { rgb <0.9, 0.5, 0.3> } scale 1.4 translate <0, 0.2, 0> }
#elseif (Variant = 0)
  // A sphere bigger than its box: the cut faces are flat.
  isosurface { function { f_sphere(x, y, z, 1.2) } contained_by { box { -1, 1 } }
    pigment { rgb <0.9, 0.3, 0.2> } rotate <20, 30, 0> translate <-2.5, 0, 0> }
  // The same, open: hollow where the box cuts it.
  isosurface { function { f_sphere(x, y, z, 1.2) } contained_by { box { -1, 1 } } open
    pigment { rgb <0.3, 0.8, 0.3> } rotate <20, 30, 0> translate <0, 0, 0> }
  // A noisy torus in a sphere container, with a threshold.
  isosurface { function { f_torus(x, y, z, 0.8, 0.35) - f_noise3d(x * 3, y * 3, z * 3) * 0.4 }
    threshold -0.1 contained_by { sphere { 0, 1.3 } } max_gradient 3
    pigment { function { Stone(x, y, z).gray } } rotate -50 * x translate <2.5, 0, 0> }
  // Below: a wavy sheet coloured by a pattern function, scaled unevenly.
  isosurface { function { y - 0.2 * sin(x * 4) * cos(z * 3) } contained_by { box { <-4, -0.5, -1>, <4, 0.5, 1> } }
    pigment { function { Bands(x, y, z) } colour_map { [0 rgb <0.2, 0.2, 0.9>] [1 rgb 1] } }
    scale <1, 0.6, 0.5> translate <0, -0.8, -2> }
#else
  // Glass: the far side is found only with max_trace 2 (or all_intersections).
  isosurface { function { f_rounded_box(x, y, z, 0.2, 0.8, 0.8, 0.8) } contained_by { box { -1, 1 } }
    max_trace 2 pigment { rgbf <0.9, 0.9, 1, 0.8> } finish { reflection 0.1 } interior { ior 1.3 }
    translate <-2.5, 0, 0> }
  difference {
    box { -0.9, 0.9 }
    isosurface { function { f_sphere(x, y, z, 1) } contained_by { box { -1.1, 1.1 } } all_intersections }
    pigment { rgb <0.9, 0.7, 0.2> } rotate <30, 40, 0>
  }
  // evaluate raises the gradient bound where it finds steeper slopes.
  isosurface { function { f_sphere(x, y, z, 0.9) + f_noise3d(x * 6, y * 6, z * 6) * 0.3 }
    contained_by { sphere { 0, 1.3 } } evaluate 1, 2, 0.8
    pigment { rgb <0.5, 0.6, 0.9> } translate <2.5, 0, 0> }
#end
