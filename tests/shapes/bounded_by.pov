// bounded_by as POV-Ray 3.7 applies it: every shape here is bounded by two crossed slabs, and a
// ray must meet (or start in) both, so each shows only where the slabs cross. (Left out: flat
// triangles, polygons and meshes, which POV-Ray draws whole, and a scene of one object, where
// POV-Ray also draws a sphere, box or plane whole; lumen cuts those too.)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -20> look_at 0 right x * 24 up y * 12 }
light_source { <-20, 30, -40> rgb 1 }
#macro Bounded(Obj, Col, Row)
  object { Obj
    pigment { rgb <0.9, 0.7, 0.4> } finish { ambient 0.2 diffuse 0.8 }
    bounded_by { box { <-2, -0.3, -2>, <2, 0.3, 2> } box { <-0.3, -2, -2>, <0.3, 2, 2> } }
    translate <-10.5 + Col * 3, 4.5 - Row * 3, 0> }
#end
Bounded(sphere { 0, 1.2 }, 0, 0)
Bounded(box { -1, 1 rotate <20, 30, 0> }, 1, 0)
Bounded(disc { 0, <0.2, 0.3, -1>, 1.2 }, 2, 0)
Bounded(height_field { function 8, 8 { 0.5 + 0.3 * x } translate -0.5 scale <2.4, 1, 2.4> rotate -x * 80 }, 6, 0)
Bounded(bicubic_patch { type 1 flatness 0 u_steps 3 v_steps 3
  <-1.2, -1.2, 0>, <-0.4, -1.2, -0.5>, <0.4, -1.2, -0.5>, <1.2, -1.2, 0>,
  <-1.2, -0.4, -0.5>, <-0.4, -0.4, -1>, <0.4, -0.4, -1>, <1.2, -0.4, -0.5>,
  <-1.2, 0.4, -0.5>, <-0.4, 0.4, -1>, <0.4, 0.4, -1>, <1.2, 0.4, -0.5>,
  <-1.2, 1.2, 0>, <-0.4, 1.2, -0.5>, <0.4, 1.2, -0.5>, <1.2, 1.2, 0> }, 7, 0)
Bounded(cone { -z, 1.2, z, 0.6 rotate <30, 20, 0> }, 0, 1)
Bounded(cylinder { -z, z, 1.1 rotate <30, 20, 0> }, 1, 1)
Bounded(torus { 0.9, 0.3 rotate x * 70 }, 2, 1)
Bounded(superellipsoid { <0.5, 0.5> scale 1.1 }, 3, 1)
Bounded(lathe { linear_spline 3, <0, -1.2>, <1.1, 0>, <0, 1.2> rotate x * 60 }, 4, 1)
Bounded(sor { 4, <0, -1.5>, <1, -1>, <1, 1>, <0, 1.5> rotate x * 60 }, 5, 1)
Bounded(prism { -1, 1, 4, <-1, -1>, <1, -1>, <0, 1>, <-1, -1> rotate x * 70 }, 6, 1)
Bounded(blob { threshold 0.5 sphere { 0, 1.6, 1 } sphere { <0.6, 0.4, 0>, 1, 1 } }, 7, 1)
Bounded(sphere_sweep { linear_spline 2, <-1, -0.5, 0>, 0.6, <1, 0.5, 0>, 0.6 }, 0, 2)
Bounded(ovus { 1, 0.6 }, 1, 2)
Bounded(quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1.2 }, 2, 2)
Bounded(quartic { <1, 0, 0, 0, 1, 0, 0, 1, 0, -1.5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, -0.5> }, 3, 2)
Bounded(union { sphere { 0, 1 } sphere { <0.7, 0.5, -0.3>, 0.6 } }, 4, 2)
Bounded(intersection { sphere { 0, 1.2 } plane { <1, 1, -1>, 0.4 } }, 5, 2)
Bounded(difference { box { -1, 1 } sphere { <0, 0, -1>, 0.8 } }, 6, 2)
Bounded(object { sphere { 0, 1 } scale 1.2 }, 7, 2)
