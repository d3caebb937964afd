// Stability: camera rays tangent to silhouettes. Orthographic rays 0.1 apart, with columns
// and rows placed exactly on the silhouettes: the sphere's left and right edges (x = -2.2 and
// -0.2), the box's side faces (x = 0.2 and 2.2, which the rays run inside) and the box's top
// and bottom faces (y = 1 and -1). Expected: flat colours (ambient only) in the interiors,
// the background elsewhere, and no other colour anywhere. Rays exactly tangent to the sphere
// miss it, as in POV-Ray (pixels 10,12 top, 0,22 left, 20,22 right, 16,14 on the rim); the
// differential suite compares this scene with POV-Ray's render too.
// expect: size 45x45
// expect: colours 1 0.2 0.2  0.2 1 0.2  0 0 0.1
// expect: uniform 8 18 12 26 1 0.2 0.2 0
// expect: uniform 26 14 42 30 0.2 1 0.2 0
// expect: uniform 0 0 44 8 0 0 0.1 0
// expect: uniform 0 36 44 44 0 0 0.1 0
// expect: uniform 10 12 10 12 0 0 0.1 0
// expect: uniform 0 22 0 22 0 0 0.1 0
// expect: uniform 20 22 20 22 0 0 0.1 0
// expect: uniform 16 14 16 14 0 0 0.1 0
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> direction z right 4.5 * x up 4.5 * y }
background { rgb <0, 0, 0.1> }
light_source { <3, 10, -10> rgb 1 }
sphere { <-1.2, 0, 0>, 1 pigment { rgb <1, 0.2, 0.2> } finish { ambient 1 diffuse 0 } }
box { <0.2, -1, -1>, <2.2, 1, 1> pigment { rgb <0.2, 1, 0.2> } finish { ambient 1 diffuse 0 } }
