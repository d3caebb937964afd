// pavement as a normal: POV-Ray differences the pattern's value like any pattern without a
// normal of its own (square, triangular and hexagonal cells, shaped corners), lit at a
// grazing angle so the bevels show.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 10, 0> look_at 0 right 8*x up 6*z }
light_source { <-3, 10, -6> rgb 1 }
#declare F = finish { ambient 0 diffuse 1 specular 0.4 }
#ifndef (Sides) #declare Sides = 4; #end
plane { y, 0 pigment { rgb 0.8 } finish { F }
  normal { pavement 0.6 number_of_sides Sides number_of_tiles 4 pattern 2 exterior 1 interior 2 form 1
    scale 0.7 translate <0.013, 0, 0.031> } }
