// sphere_sweep probes (tests/differential/scenes.txt runs each Variant against POV-Ray):
//   0 linear_spline: tapering tubes, a sphere swallowing its neighbour, a coincident pair,
//     a zero end radius (a cone's tip). Not here: a radius changing sign, which POV-Ray
//     draws without the negative spheres (render/shapes/sphere_sweep.hpp)
//   1 b_spline and cubic_spline through the same spheres, with varying radii, rotated
//   2 in CSG: intersection with a box, difference from a box, a scaled sweep
//   3 the camera and a light inside a sweep (its inner surface), a sweep along the view axis
// POV-Ray's own solver leaves dark specks on spline sweeps at the default tolerance (its
// manual says so): the spline variants raise it, as the manual advises.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (Variant) #declare Variant = 0; #end
#if (Variant = 3)
  camera { location <0.2, 0.1, -0.3> look_at <0.6, 0.3, 3> angle 80 }
  light_source { <0.4, 0.3, 1.5> rgb 0.8 }
#else
  camera { location <0, 3, -9> look_at <0, 0.4, 0> angle 45 }
#end
light_source { <-6, 10, -8> rgb 1 }
light_source { <8, 4, -3> rgb 0.4 }
background { rgb <0.1, 0.12, 0.2> }
plane { y, -1.5 pigment { checker rgb 0.8 rgb 0.4 } }
#declare Skin = texture { pigment { rgb <0.9, 0.4, 0.2> } finish { phong 0.8 specular 0.2 } }
#declare Blue = texture { pigment { rgb <0.2, 0.4, 0.9> } finish { phong 0.6 } }

#switch (Variant)
#case (0)
  sphere_sweep { linear_spline 4, <-3, -1, 0>, 0.5, <-2, 1, 0.5>, 0.2, <-1, 0, -0.5>, 0.35,
                 <0, 1.5, 0>, 0.1 texture { Skin } }
  sphere_sweep { linear_spline 3 <0.5, -1, 0> 0.2 <1, -0.5, 0> 0.9 <1, -0.5, 0> 0.9 texture { Blue } }
  sphere_sweep { linear_spline 3, <1.5, 0.8, 0>, 0.4, <2.5, 1.6, 0>, 0.25, <3, 0, -1>, 0
                 texture { Skin } rotate 10*y }
#break
#case (1)
  #declare Path = array[7] { <-3, -1, 0>, <-2, 1, 0.5>, <-1, 0, -0.5>, <0, 1.5, 0>,
                             <1, -0.5, 0.6>, <2, 1, 0>, <3, -1, 0> }
  #declare Radii = array[7] { 0.2, 0.4, 0.25, 0.5, 0.2, 0.3, 0.2 }
  sphere_sweep { b_spline 7,
    #for (i, 0, 6) Path[i], Radii[i] #end
    tolerance 1e-3 texture { Skin } translate 0.4*y }
  sphere_sweep { cubic_spline 7,
    #for (i, 0, 6) Path[i], Radii[i] * 0.6 #end
    tolerance 1e-3 texture { Blue } rotate 20*x translate <0, -0.6, 1.5> }
#break
#case (2)
  intersection {
    sphere_sweep { b_spline 5, <-3, 0, 0>, 0.5, <-2, 1, 0>, 0.7, <-1, -0.5, 0>, 0.6,
                   <0, 1, 0>, 0.5, <1, 0, 0>, 0.4 tolerance 1e-3 }
    box { <-3, -2, -0.2>, <3, 2, 2> }
    texture { Skin } }
  difference {
    box { <0.6, -1.2, -0.6>, <3, 1, 0.6> }
    sphere_sweep { linear_spline 3, <0.6, 0.4, -0.8>, 0.3, <1.8, -0.2, 0>, 0.5, <3.2, 0.6, -0.3>, 0.2 }
    texture { Blue } }
  sphere_sweep { cubic_spline 4, <0, -1, -1>, 0.2, <0, -1, -1>, 0.2, <1, 0, -1>, 0.3, <2, 0, 0>, 0.3
                 tolerance 1e-3 texture { Skin } scale <1.5, 1, 0.5> translate <-1, 1.2, -1.5> }
#break
#case (3)
  sphere_sweep { linear_spline 4, <0, 0, -1>, 1.2, <0.5, 0, 2>, 0.8, <1.5, 0.5, 4>, 1, <3, 0, 6>, 0.5
                 tolerance 1e-3 texture { Skin } }
  sphere_sweep { linear_spline 2, <-1, 0.6, 3>, 0.3, <-1.6, 0.9, 8>, 0.3 texture { Blue } }
#break
#end
