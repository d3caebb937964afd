// Render benchmark for the swept shapes (bench/render_vs_povray.sh build/lumen 2 3
// bench/swept_shapes.pov): a field of 48 lathes, prisms and sors, every spline kind and both
// sweeps, with shadows and a reflective floor, so most rays meet their polynomials.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 7, -13> look_at <0, 0.5, 0> angle 48 }
light_source { <-8, 14, -10> rgb 1 }
light_source { <10, 8, -4> rgb 0.4 }
background { rgb <0.15, 0.18, 0.25> }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.5 } finish { reflection 0.2 } }
#declare Vase = lathe { cubic_spline 9, <0, 0>, <0.4, 0>, <0.6, 0.3>, <0.35, 0.8>, <0.2, 1.1>,
  <0.35, 1.4>, <0.3, 1.5>, <0.25, 1.45>, <0.2, 1.3> }
#declare Bulb = lathe { bezier_spline 8, <0, 0>, <0.9, 0>, <0.6, 0.6>, <0.3, 0.8>,
  <0.3, 0.8>, <0.1, 1>, <0.5, 1.3>, <0, 1.4> }
#declare Cup = sor { 7, <0, -0.1>, <0.3, 0>, <0.6, 0.4>, <0.3, 0.9>, <0.25, 1.1>, <0.4, 1.3>, <0.5, 1.5> }
#declare Star = prism { cubic_spline 0, 0.8, 10,
  <0, -0.6>, <0.5, -0.2>, <0.6, 0.3>, <0.1, 0.35>, <-0.3, 0.6>, <-0.5, 0.1>, <-0.55, -0.4>,
  <0, -0.6>, <0.5, -0.2>, <0.6, 0.3> }
#declare Frustum = prism { conic_sweep bezier_spline 0.5, 1, 8,
  <0.6, 0>, <0.6, 0.8>, <-0.6, 0.8>, <-0.6, 0>, <-0.6, 0>, <-0.6, -0.8>, <0.6, -0.8>, <0.6, 0>
  rotate 180 * x translate y }
#declare Shapes = array[5] { Vase, Bulb, Cup, Star, Frustum }
#for (I, 0, 47)
  #declare X = mod(I, 8) - 3.5;
  #declare Z = div(I, 8) - 2.5;
  object { Shapes[mod(I, 5)]
    pigment { rgb <0.5 + 0.5 * sin(I), 0.5 + 0.5 * cos(1.3 * I), 0.6> }
    finish { phong 0.6 phong_size 40 }
    rotate 37 * I * y translate <1.4 * X, 0, 1.6 * Z> }
#end
