// Stability: coincident coplanar surfaces. Two boxes share the face x = 0 and have their
// front faces in one plane (z = -1); below them two identical boxes in different colours
// coincide everywhere; a sunken box's top face lies in the floor plane y = -1. Expected: no
// speckle where surfaces coincide: one surface wins every tie, so each region is one flat
// colour (ambient only), and the same image as POV-Ray. (Which coincident surface POV shows
// depends on its bounding hierarchy: here the blue box and the floor; with only the sunken
// box written before the floor, the box. lumen lets the object written first win.)
// expect: size 48x36
// expect: povray 45
// expect: uniform 14 9 22 17 1 0.2 0.2 0
// expect: uniform 25 9 33 17 0.2 1 0.2 0
// expect: uniform 15 20 32 25 0.2 0.2 1 0
// expect: same 0 26 47 35
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> look_at <0, 0, 0> }
background { rgb <0, 0, 0.1> }
light_source { <3, 10, -10> rgb 1 }
#declare Flat = finish { ambient 1 diffuse 0 };
box { <-1.5, 0, -1>, <0, 1.5, 1> pigment { rgb <1, 0.2, 0.2> } finish { Flat } }
box { <0, 0, -1>, <1.5, 1.5, 1> pigment { rgb <0.2, 1, 0.2> } finish { Flat } }
// Two identical boxes, different colours: the surfaces coincide everywhere.
box { <-1.5, -1, -1>, <1.5, 0, 1> pigment { rgb <0.2, 0.2, 1> } finish { Flat } }
box { <-1.5, -1, -1>, <1.5, 0, 1> pigment { rgb <1, 1, 0.2> } finish { Flat } }
// The floor and the top face of a sunken box share the plane y = -1.
plane { y, -1 pigment { rgb <0.6, 0.6, 0.6> } finish { Flat } }
box { <-4, -2, -4>, <4, -1, -2> pigment { rgb <1, 0.5, 0> } finish { Flat } }
