// Isosurfaces from functions.inc: a noisy torus, a twisted rounded box, a blob of spheres and a
// noise landscape, textured by function patterns. The benchmark of compiled functions
// (bench/isosurface.sh): render at 640x480 against POV-Ray.
#version 3.7;
#include "functions.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.6, 0> angle 48 }
light_source { <-6, 12, -9> rgb 1 }
light_source { <8, 5, -4> rgb 0.35 }
sky_sphere { pigment { gradient y colour_map { [0 rgb <0.8, 0.85, 1>] [1 rgb <0.3, 0.45, 0.8>] } } }

// The ground: a noise height field as an isosurface.
isosurface {
  function { y + 1 - f_noise3d(x * 0.7, 0, z * 0.7) * 0.8 - f_noise3d(x * 3, 0, z * 3) * 0.1 }
  contained_by { box { <-12, -1.5, -4>, <12, 0, 16> } }
  max_gradient 1.5
  pigment { function { f_noise3d(x, y * 4, z) } colour_map { [0 rgb <0.35, 0.3, 0.2>] [1 rgb <0.6, 0.65, 0.4>] } }
}
// A torus roughened by noise.
isosurface {
  function { f_torus(x, y, z, 1.1, 0.4) - f_noise3d(x * 4, y * 4, z * 4) * 0.25 }
  contained_by { box { <-1.8, -0.8, -1.8>, <1.8, 0.8, 1.8> } }
  max_gradient 2.5
  pigment { granite colour_map { [0 rgb <0.8, 0.3, 0.2>] [1 rgb <1, 0.8, 0.5>] } scale 0.8 }
  finish { specular 0.4 roughness 0.02 }
  rotate <-60, 20, 0> translate <-2.6, 1.3, 0.5>
}
// A rounded box twisted about y.
#declare Twist = function(x, y, z, a) { f_rounded_box(x * cos(a * y) - z * sin(a * y), y, x * sin(a * y) + z * cos(a * y), 0.15, 0.6, 1.2, 0.6) }
isosurface {
  function { Twist(x, y, z, 1.1) }
  contained_by { box { <-1, -1.3, -1>, <1, 1.3, 1> } }
  max_gradient 2.2
  pigment { function { abs(sin(y * 8)) } colour_map { [0 rgb <0.2, 0.4, 0.9>] [1 rgb <0.9, 0.95, 1>] } }
  finish { specular 0.6 roughness 0.01 reflection 0.1 }
  translate <0.3, 1.3, 1.5>
}
// Three spheres melted together (f_blob2 fields), with noise on top.
isosurface {
  function { 1.1 - exp(-3 * (pow(x + 0.6, 2) + y * y + z * z)) - exp(-3 * (pow(x - 0.6, 2) + y * y + z * z))
             - exp(-3 * (x * x + pow(y - 0.8, 2) + z * z)) + f_noise3d(x * 5, y * 5, z * 5) * 0.15 }
  contained_by { sphere { 0, 1.8 } }
  max_gradient 3
  pigment { rgb <0.95, 0.85, 0.3> }
  finish { specular 0.5 roughness 0.02 }
  translate <2.8, 0.9, 0>
}
