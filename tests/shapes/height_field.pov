// height_field: one of the probe images of tests/data/images (make_height_images.py) as a lit
// field seen at an angle, with a checker in 3D that shows where its triangles lie.
// Declare Kind: 0 grey 8-bit PNG, 1 grey 16-bit PNG, 2 RGB 8-bit PNG (red high byte, green
// low byte), 3 palette PNG, 4 PGM, 5 PPM (ASCII), 6 grey TGA, 7 RLE true-colour TGA,
// 8 a function image (function 30, 20 { expr }, y of the function along -z).
// Smooth (0/1), Water (water_level), Csg (1: the field minus a sphere, intersected with a box).
#version 3.7;
#ifndef (Kind) #declare Kind = 0; #end
#ifndef (Smooth) #declare Smooth = 0; #end
#ifndef (Water) #declare Water = 0; #end
#ifndef (Csg) #declare Csg = 0; #end
global_settings { assumed_gamma 1 }
camera { location <0.3, 3.6, -5.2> look_at <0, 0.3, 0> angle 45 }
light_source { <-3, 6, -4> rgb 1 }
light_source { <4, 3, -1> rgb 0.35 shadowless }
background { rgb <0.2, 0.3, 0.4> }
#declare Dir = "../data/images/";
#declare Field = height_field {
    #switch (Kind)
    #case (0) png concat(Dir, "hf_grey8.png") #break
    #case (1) png concat(Dir, "hf_grey16.png") #break
    #case (2) concat(Dir, "hf_rgb8.png") #break
    #case (3) png concat(Dir, "hf_palette.png") #break
    #case (4) pgm concat(Dir, "hf_grey.pgm") #break
    #case (5) ppm concat(Dir, "hf_rgb.ppm") #break
    #case (6) tga concat(Dir, "hf_grey.tga") #break
    #case (7) concat(Dir, "hf_rgb_rle.tga") #break
    #case (8) function 30, 20 { 0.45 + 0.3 * sin(x * 7) * cos(y * 4) + 0.2 * y * y } #break
    #end
    water_level Water
    #if (Smooth) smooth #end
    pigment { checker rgb <1, 0.45, 0.2> rgb <0.9, 0.9, 0.8> scale 0.25 }
    finish { phong 0.5 }
    translate <-0.5, 0, -0.5> scale <4, 1.4, 3> rotate 15*y
}
#if (Csg)
    difference {
        intersection {
            object { Field }
            box { <-1.6, -1, -2>, <1.7, 2, 1.2> pigment { rgb <0.3, 0.8, 0.4> } }
        }
        sphere { <0.4, 0.9, -0.3>, 0.7 pigment { rgb <0.4, 0.5, 1> } }
    }
#else
    object { Field }
#end
plane { y, -0.01 pigment { rgb 0.5 } }
