// Image patterns against POV-Ray: the probe images of tests/data/images (make_map_images.py)
// as image_map, bump_map, material_map and image_pattern. Declare Kind:
//  0 planar, tiled        1 planar once, bilinear (off the map: the checker behind shows)
//  2 bicubic              3 normalised distance   4 spherical on a turned sphere
//  5 cylindrical once     6 torus                 7 RGBA alpha over a checker
//  8 palette: tRNS, `filter all`, `transmit N`    9 gAMA chunk   10 sRGB chunk   11 PPM
// 12 `gamma 2.2`          13 bump_map (bump_size 3, bilinear)   14 bump_map use_index
// 15 material_map, palette                        16 material_map, true colour
// 17 image_pattern with a colour_map              18 image_pattern use_alpha
// 19 uv_mapping on a sphere                       20 `transmit all` and `filter all`
// 21 GIF, interlaced, a transparent entry, `filter 2,`
// Legacy=1: no #version 3.7 (the 3.6 gamma rule and the legacy opacity).
#ifndef (Kind) #declare Kind = 0; #end
#ifndef (Legacy) #declare Legacy = 0; #end
#if (Legacy)
  #version 3.6;
  global_settings { assumed_gamma 2.2 }
#else
  #version 3.7;
  global_settings { assumed_gamma 1 }
#end
#declare Dir = "../data/images/";
#declare Flat = finish { ambient 1 diffuse 0 }
#declare Lit = finish { ambient 0.1 diffuse 0.9 }
background { rgb <0.2, 0.3, 0.4> }
light_source { <-3, 5, -6> rgb 1 }
#declare Behind = plane { z, 2 pigment { checker rgb <0.9, 0.5, 0.1> rgb <0.1, 0.3, 0.8> scale 0.5 } finish { Flat } }

#macro Front(P)  // a plane facing the camera, the image's unit square scaled to 2 x 1.4
  camera { orthographic location <0, 0, -5> look_at 0 right 4 * x up 3 * y }
  plane { -z, 0 pigment { P translate <-0.5, -0.5, 0> scale <2, 1.4, 1> } finish { Flat } }
#end
#macro Once(P)  // the image once, on a square in front of a checker
  camera { orthographic location <0, 0, -5> look_at 0 right 4 * x up 3 * y }
  box { <-1.5, -1.2, 0>, <1.5, 1.2, 0.1> pigment { P translate <-0.5, -0.5, 0> scale <2, 1.4, 1> } finish { Flat } }
  object { Behind }
#end
#macro Seen(O)  // an object seen at an angle
  camera { location <0, 1.2, -4> look_at 0 angle 45 }
  object { O }
  object { Behind }
#end

#switch (Kind)
#case (0) Front(pigment { image_map { png concat(Dir, "map_rgb.png") } scale 0.4 }) #break
#case (1) Once(pigment { image_map { png concat(Dir, "map_rgb.png") once interpolate 2 } }) #break
#case (2) Front(pigment { image_map { concat(Dir, "map_rgb.png") interpolate 3 } }) #break
#case (3) Front(pigment { image_map { concat(Dir, "map_rgb.png") interpolate 4 } }) #break
#case (4) Seen(sphere { 0, 1.2 pigment { image_map { png concat(Dir, "map_rgb.png") map_type 1 } rotate <20, 30, 0> } finish { Lit } }) #break
#case (5) Seen(cylinder { <0, -0.8, 0>, <0, 0.8, 0>, 1 open
    pigment { image_map { png concat(Dir, "map_rgb.png") map_type 2 once } translate -0.5 * y scale <1, 2.2, 1> rotate 40 * y }
    finish { Flat } }) #break
#case (6) Seen(torus { 1, 0.4 pigment { image_map { png concat(Dir, "map_rgb.png") map_type 5 interpolate 2 } } finish { Lit } rotate -50 * x }) #break
#case (7) Once(pigment { image_map { png concat(Dir, "map_rgba.png") } }) #break
#case (8) Once(pigment { image_map { png concat(Dir, "map_palette.png") filter all 0.3 transmit 2, 0.8 } }) #break
#case (9) Front(pigment { image_map { png concat(Dir, "map_gama.png") } }) #break
#case (10) Front(pigment { image_map { png concat(Dir, "map_srgb.png") } }) #break
#case (11) Front(pigment { image_map { ppm concat(Dir, "map_rgb.ppm") } }) #break
#case (12) Front(pigment { image_map { png concat(Dir, "map_rgb.png") gamma 2.2 } }) #break
#case (13)
  camera { location <0, 0, -5> look_at 0 angle 40 }
  plane { -z, 0 pigment { rgb 0.8 } finish { Lit }
    normal { bump_map { png concat(Dir, "map_grey8.png") bump_size 3 interpolate 2 } translate <-0.5, -0.5, 0> scale <2, 1.4, 1> rotate 10 * z } }
  #break
#case (14)
  camera { location <0, 0, -5> look_at 0 angle 40 }
  sphere { 0, 1.5 pigment { rgb 0.8 } finish { Lit }
    normal { bump_map { png concat(Dir, "map_palette.png") use_index } 0.05 translate <-0.5, -0.5, 0> scale 2 } }
  #break
#case (15)
  Seen(box { -1, 1 texture { material_map { png concat(Dir, "map_palette.png")
      texture { pigment { rgb <1, 0.2, 0.1> } finish { Lit } }
      texture { pigment { checker rgb 1 rgb 0 scale 0.2 } finish { Flat } }
      texture { pigment { rgb <0.2, 0.9, 0.3> } finish { Lit phong 1 } }
      texture { pigment { rgb <0.3, 0.3, 1> } normal { bumps 0.6 scale 0.1 } finish { Lit } } }
    translate <-0.5, -0.5, 0> scale 2 } rotate <-20, 30, 0> })
  #break
#case (16)
  camera { orthographic location <0, 0, -5> look_at 0 right 4 * x up 3 * y }
  plane { -z, 0 texture { material_map { png concat(Dir, "map_rgb.png")
      texture { pigment { rgb <1, 0.2, 0.1> } finish { Flat } }
      texture { pigment { rgb <0.2, 0.9, 0.3> } finish { Flat } }
      texture { pigment { rgb <0.3, 0.3, 1> } finish { Flat } } }
    translate <-0.5, -0.5, 0> scale <2, 1.4, 1> } }
  #break
#case (17) Front(pigment { image_pattern { png concat(Dir, "map_rgb.png") interpolate 2 }
    color_map { [0 rgb <0, 0, 0.3>] [0.5 rgb <1, 0.4, 0>] [1 rgb <1, 1, 0.8>] } }) #break
#case (18) Front(pigment { image_pattern { png concat(Dir, "map_rgba.png") use_alpha }
    color_map { [0 rgb <0, 0.5, 0.2>] [1 rgb <1, 0.9, 0.8>] } }) #break
#case (19) Seen(sphere { 0, 1.2 pigment { uv_mapping image_map { png concat(Dir, "map_rgb.png") interpolate 2 } } finish { Lit } rotate 60 * y }) #break
#case (20) Once(pigment { image_map { png concat(Dir, "map_rgb.png") filter all 0.5 transmit all 0.25 } }) #break
#case (21) Once(pigment { image_map { gif concat(Dir, "map_palette.gif") filter 2, 0.6 interpolate 2 } }) #break
#end
