// Render benchmark for height_field (bench/render_vs_povray.sh build/lumen 2 3
// bench/height_field.pov): the larger images of POV-Ray's include folder as fields filling the
// view, Mount1.png (250 x 250, flat normals) and Mount2.png (smooth), and fract003.png
// (320 x 200 palette, with water), with shadows and a reflective lake.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -11> look_at <0, 0.5, 0> angle 60 }
light_source { <-20, 30, -15> rgb 1 }
background { rgb <0.5, 0.6, 0.8> }
plane { y, 0.05 pigment { rgb <0.2, 0.3, 0.5> } finish { reflection 0.3 } }
height_field { png "Mount1.png"
    pigment { gradient y color_map { [0 rgb <0.3, 0.5, 0.2>] [0.6 rgb <0.5, 0.4, 0.3>] [1 rgb 1] } }
    translate <-0.5, 0, -0.5> scale <10, 3, 10> translate <-5, 0, 3> }
height_field { png "Mount2.png" smooth
    pigment { gradient y color_map { [0 rgb <0.3, 0.5, 0.2>] [0.6 rgb <0.5, 0.4, 0.3>] [1 rgb 1] } }
    finish { phong 0.3 }
    translate <-0.5, 0, -0.5> scale <10, 3.5, 10> translate <5, 0, 3> }
height_field { png "fract003.png" water_level 0.1
    pigment { rgb <0.8, 0.6, 0.4> }
    translate <-0.5, 0, -0.5> scale <12, 1.2, 7.5> translate <0, 0, -3> }
