// parametric (render/shapes/parametric.cpp) against POV-Ray: a Moebius strip in a box, a
// uv-mapped torus in a sphere container, a wave sheet from functions of (u, v) with reversed
// uv corners, shadows on a floor, transforms; Variant 1: the same with precompute (all axes,
// then x and z only) seen from above, where POV-Ray's depths are furthest from the surface.
#version 3.7;
#ifndef (Variant) #declare Variant = 0; #end
global_settings { assumed_gamma 1.0 }
#if (Variant = 0)
  camera { location <0, 3, -8> look_at <0, 0.3, 0> angle 50 }
#else
  camera { location <0.01, 9, 0> look_at 0 sky z angle 50 }
#end
light_source { <-5, 10, -8> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
plane { y, -1.2 pigment { checker rgb 0.8 rgb 0.5 } }
#declare R = 0.8;
#declare Sheet = function(u, v) { 0.3 * sin(3 * u) * cos(2 * v) }
parametric {
  function { cos(u) + v * cos(u / 2) * cos(u) }
  function { sin(u) + v * cos(u / 2) * sin(u) }
  function { v * sin(u / 2) }
  <0, -0.3>, <2 * pi, 0.3>
  contained_by { box { -2, 2 } }
  #if (Variant = 1) precompute 14, x, y, z #end
  pigment { rgb <0.9, 0.3, 0.2> } finish { specular 0.4 }
  rotate <-60, 33, 0> translate <-2.5, 0, 0>
}
parametric {
  function { (1 + R * cos(v)) * cos(u) }
  function { R * sin(v) }
  function { (1 + R * cos(v)) * sin(u) }
  <0, 0>, <2 * pi, 2 * pi>
  contained_by { sphere { 0, 1.9 } }
  max_gradient 2
  #if (Variant = 1) precompute 12, x, z #end
  uv_mapping pigment { checker rgb <0.2, 0.8, 0.3> rgb 1 scale <0.5, 0.5, 1> }
  scale 0.7 rotate <-30, 0, 0> translate <1.8, 0, 0>
}
parametric {
  function { u } function { Sheet(u, v) } function { v }
  <2, 1>, <-2, -1>
  contained_by { box { <-2, -1, -1>, <2, 1, 1> } }
  accuracy 0.002
  pigment { rgb <0.3, 0.4, 0.9> }
  scale <1, 1, 0.6> translate <0, -0.7, -2>
}
