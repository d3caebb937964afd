// sphere_sweep: a trefoil knot (a closed b_spline: its first three spheres repeated at the
// end), a spring (a cubic_spline helix with a swelling radius) and a wire tetrahedron of
// linear_spline tubes, in gold, glazed blue and matte red on a reflective floor.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }

camera {
  location <0, 4.5, -10>
  look_at  <0, 1.2, 0>
  right x*image_width/image_height
  angle 48
}
light_source { <-6, 12, -9> color rgb 1 }
light_source { <9, 6, -4> color rgb 0.35 }
background { color rgb <0.12, 0.14, 0.22> }
plane { y, 0
  pigment { checker color rgb 0.75 color rgb 0.3 scale 1.2 }
  finish { diffuse 0.8 reflection 0.12 } }

// The knot: (sin t + 2 sin 2t, cos t - 2 cos 2t, -sin 3t), 24 spheres around, 3 more to close.
#declare N = 24;
sphere_sweep { b_spline N + 3,
  #for (i, 0, N + 2)
    #declare T = 2 * pi * i / N;
    <sin(T) + 2 * sin(2 * T), cos(T) - 2 * cos(2 * T), -sin(3 * T)>, 0.42 + 0.1 * sin(3 * T)
  #end
  tolerance 1e-3
  texture {
    pigment { color rgb <1, 0.72, 0.3> }
    finish { ambient 0.05 diffuse 0.6 specular 0.7 roughness 0.02 metallic reflection 0.3 }
  }
  scale 0.55 rotate <-20, 20, 0> translate <-2.1, 2.1, 0.8>
}

// The spring: eight turns up a helix, thickest in the middle.
#declare Turns = 8;
#declare M = Turns * 8;
sphere_sweep { cubic_spline M + 3,
  #for (i, -1, M + 1)
    #declare A = 2 * pi * i / 8;
    <0.9 * cos(A), 0.3 + 3.2 * i / M, 0.9 * sin(A)>, 0.09 + 0.08 * sin(pi * i / M)
  #end
  tolerance 1e-3
  texture {
    pigment { color rgb <0.2, 0.45, 1> }
    finish { ambient 0.05 diffuse 0.7 phong 0.9 phong_size 60 reflection 0.1 }
  }
  translate <2.3, 0, 0.6>
}

// The tetrahedron: two linear sweeps along its six edges, tapering from corner to corner.
#declare P0 = <0, 0.2, -1.4>;
#declare P1 = <1.2, 0.2, 0.7>;
#declare P2 = <-1.2, 0.2, 0.7>;
#declare P3 = <0, 2.2, 0>;
#declare Red = texture { pigment { color rgb <0.85, 0.15, 0.1> } finish { diffuse 0.8 phong 0.3 } }
union {
  sphere_sweep { linear_spline 5, P0, 0.12, P1, 0.06, P2, 0.12, P0, 0.06, P3, 0.12 }
  sphere_sweep { linear_spline 3, P1, 0.06, P3, 0.12, P2, 0.12 }
  texture { Red }
  translate <0, 0, -1.8>
}
