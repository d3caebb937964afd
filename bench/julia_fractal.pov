// Render benchmark for julia_fractal (bench/render_vs_povray.sh build/lumen 2 3
// bench/julia_fractal.pov): three quaternion sets (sqr at two precisions, cube) and a
// hypercomplex one filling the frame, with shadows on a floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.3, 0> angle 50 }
light_source { <-8, 14, -10> rgb 1 }
background { rgb <0.15, 0.18, 0.25> }
plane { y, -1.6 pigment { checker rgb 0.8 rgb 0.5 } }
#declare Finish = finish { phong 0.5 specular 0.2 }
julia_fractal { <-0.083, 0.0, -0.83, -0.025> quaternion sqr max_iteration 8 precision 20
    pigment { rgb <1, 0.7, 0.4> } finish { Finish } rotate <-30, 20, 0> translate <-1.9, 0, 0.5> }
julia_fractal { <-0.03, 0.5, -0.2, -0.5> quaternion sqr max_iteration 10 precision 100
    pigment { rgb <0.5, 0.8, 1> } finish { Finish } rotate <0, 40, 0> translate <1.9, 0, 0.5> }
julia_fractal { <-0.033, -0.6, -0.93, -0.025> quaternion cube max_iteration 6 precision 50
    pigment { rgb <0.7, 1, 0.6> } finish { Finish } scale 0.9 translate <0, 1.6, 2.5> }
julia_fractal { <0.2, 0.1, 0.59, -0.2> hypercomplex sqr max_iteration 7 precision 30
    pigment { rgb <0.9, 0.6, 0.9> } finish { Finish } scale 0.8 rotate <83, 0, -70> translate <0, -0.4, -1.2> }
