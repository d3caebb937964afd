// Image maps with the project's own probe images (tests/data/images, made by
// make_map_images.py): a planar map tiled on the floor, a spherical map on a ball, a
// cylindrical label, a bump-mapped wall and a material_map box. Renders as POV-Ray 3.7 does
// (tests/differential).
#version 3.7;
global_settings { assumed_gamma 1 }
#declare Dir = "../tests/data/images/";
camera { location <0, 3, -8> look_at <0, 1, 0> angle 45 }
light_source { <-4, 8, -6> rgb 1 }
light_source { <5, 3, -4> rgb 0.3 shadowless }
background { rgb <0.3, 0.4, 0.6> }
plane { y, 0 pigment { image_map { png concat(Dir, "map_rgb.png") interpolate 2 } rotate 90 * x scale 2 }
  finish { diffuse 0.8 } }
sphere { <-2, 1, 0>, 1 pigment { image_map { png concat(Dir, "map_rgb.png") map_type 1 interpolate 2 } rotate <0, 40, 10> }
  finish { phong 0.5 } }
cylinder { <0.2, 0.01, 1>, <0.2, 1.9, 1>, 0.7
  pigment { image_map { png concat(Dir, "map_rgba.png") map_type 2 once } scale <1, 2, 1> rotate -30 * y }
  finish { phong 0.3 } }
box { <-5, 0, 4>, <5, 4, 4.2> pigment { rgb 0.85 }
  normal { bump_map { png concat(Dir, "map_grey8.png") bump_size 2 interpolate 2 } scale 1.5 } }
box { -0.7, 0.7 rotate <0, 35, 0> translate <2.6, 0.7, -0.5>
  texture { material_map { png concat(Dir, "map_palette.png")
      texture { pigment { rgb <1, 0.25, 0.1> } finish { phong 0.6 } }
      texture { pigment { rgb <0.95, 0.9, 0.2> } }
      texture { pigment { rgb <0.2, 0.5, 1> } finish { reflection 0.2 } }
      texture { pigment { checker rgb 1 rgb 0 scale 0.1 } } }
    translate <-0.5, -0.5, 0> scale 1.4 } }
