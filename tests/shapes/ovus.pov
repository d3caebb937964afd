// ovus probes (tests/differential/scenes.txt runs each Variant against POV-Ray):
//   0 three ovuses (the lemon at the middle, at the bottom, a thin top), scaled and turned
//   1 in CSG: cut by a box and subtracted from a box
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (Variant) #declare Variant = 0; #end
camera { location <0, 2.5, -7> look_at <0, 0.6, 0> angle 45 }
light_source { <-6, 10, -8> rgb 1 }
light_source { <8, 4, -3> rgb 0.4 }
background { rgb <0.1, 0.12, 0.2> }
plane { y, -1 pigment { checker rgb 0.8 rgb 0.4 } }
#declare Skin = texture { pigment { rgb <0.9, 0.4, 0.2> } finish { phong 0.8 } }
#if (Variant = 0)
  ovus { 1, 0.6 texture { Skin } translate -2.2*x }
  ovus { 0.5, 0.9 texture { Skin } rotate 30*z translate 0.3*y }
  ovus { 0.7, 0.15 texture { Skin } scale <1, 1.4, 1> rotate -20*x translate <2.2, 0, 0> }
#else
  intersection { ovus { 1, 0.6 } box { <-2, -2, -0.4>, <2, 1.2, 2> } texture { Skin } rotate 40*y translate -1.5*x }
  difference { box { <-0.9, -1, -0.9>, <0.9, 0.8, 0.9> } ovus { 0.6, 0.5 translate <0, 0.2, -0.7> } texture { Skin } rotate -30*y translate 1.6*x }
#end
