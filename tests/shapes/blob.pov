// blob probes (tests/differential/scenes.txt runs each Variant against POV-Ray):
//   0 spheres and cylinders, negative strength, transformed components, a transformed blob
//   1 components with textures of their own, blended by density
//   2 sturm, and blobs in CSG (intersection, difference)
//   3 the old `component` form, hierarchy off, a threshold above most components' strength
//   4 the camera inside the blob
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (Variant) #declare Variant = 0; #end
#if (Variant = 4)
  camera { location <0.3, 0.2, -0.4> look_at <1, 0.5, 2> angle 90 }
#else
  camera { location <0, 3, -8> look_at <0, 0.3, 0> angle 45 }
#end
light_source { <-6, 10, -8> rgb 1 }
light_source { <8, 4, -3> rgb 0.4 }
background { rgb <0.1, 0.12, 0.2> }
plane { y, -1.5 pigment { checker rgb 0.8 rgb 0.4 } }
#declare Skin = texture { pigment { rgb <0.9, 0.4, 0.2> } finish { phong 0.8 specular 0.2 } }

#switch (Variant)
#case (0)
  blob { threshold 0.6
    sphere { <-1.5, 0, 0>, 1.2, 1 }
    sphere { <0, 0.2, 0>, 1.0, 1.5 }
    sphere { <0.2, 1.0, -0.4>, 0.6, -1.2 }
    cylinder { <-2, -0.6, 0>, <2, -0.6, 0.6>, 0.5, 1.2 }
    cylinder { <1.2, -1, 0>, <1.6, 1.6, 0.2>, 0.6, strength 1 }
    sphere { <1.8, 0.4, -0.6>, 0.8, 1 scale <1.5, 0.6, 1> rotate 30*z }
    texture { Skin } rotate -20*y translate 0.2*y }
#break
#case (1)
  blob { threshold 0.5
    sphere { <-1.4, 0, 0>, 1.3, 1 pigment { rgb <1, 0.2, 0.1> } }
    sphere { <0, 0.3, 0>, 1.2, 1 pigment { rgb <0.2, 0.9, 0.2> } finish { phong 1 } }
    sphere { <1.4, 0, 0>, 1.3, 1 }
    cylinder { <-1.5, -0.8, -0.5>, <1.5, -0.8, -0.5>, 0.6, 1 texture { pigment { rgb <0.2, 0.3, 1> } } translate 0.2*y }
    texture { Skin } rotate 15*y }
#break
#case (2)
  intersection {
    blob { threshold 0.4
      cylinder { <-2, 0, 0>, <2, 0, 0>, 1, 1 }
      cylinder { <0, -1.4, 0>, <0, 1.4, 0>, 1, 1 }
      sphere { 0, 1.2, -0.5 }
      sturm }
    box { <-1.8, -1.2, -0.3>, <1.8, 1.3, 1> }
    texture { Skin } rotate <-20, 30, 0> }
  difference {
    box { <-0.8, -1.5, -0.8>, <0.8, -0.4, 0.8> }
    blob { threshold 0.5 sphere { <0, -0.4, 0>, 1.2, 1 } sphere { <0.5, -0.4, -0.6>, 0.8, 1 } }
    pigment { rgb <0.3, 0.6, 1> } translate <2.6, 0, -1> }
#break
#case (3)
  blob { threshold 1.2
    component 1.0, 1.0, <0.75, 0, 0>
    component 1.0, 1.0, <-0.375, 0.64952, 0>
    component 1.0, 1.0, <-0.375, -0.64952, 0>
    component 2.0, 0.8, <0, 0, -0.3>
    hierarchy off
    texture { Skin } scale <2, 1.5, 1> rotate 40*x }
#break
#case (4)
  blob { threshold 0.5
    sphere { <0, 0, 0>, 3, 1 }
    sphere { <1, 0.5, 1>, 2, -0.4 }
    cylinder { <-2, -1, 2>, <2, 1.5, 2>, 0.8, -1 }
    texture { Skin } }
#break
#end
