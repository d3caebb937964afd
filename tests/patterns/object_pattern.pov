// The object pattern: inside an object (its own transforms, CSG) against outside, as pigment,
// texture and normal lists, the default blue/green, and the pattern's own transforms.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> direction z right 8*x up 6*y }
light_source { <-5, 5, -10> rgb 1 }
#declare Shape = difference { box { -1, 1 } sphere { 0, 1.2 } rotate 30*z }
plane { z, 0 clipped_by { box { <-4, 0, -1>, <0, 3, 1> } }
  pigment { object { Shape } translate <-2, 1.5, 0> } finish { ambient 1 diffuse 0 } }
plane { z, 0 clipped_by { box { <0, 0, -1>, <4, 3, 1> } }
  pigment { object { sphere { 0, 1 scale <1.5, 0.8, 1> } pigment { rgb <1, 0.5, 0> }, pigment { checker rgb 1 rgb 0 scale 0.25 } }
            translate <2, 1.5, 0> } finish { ambient 1 diffuse 0 } }
plane { z, 0 clipped_by { box { <-4, -3, -1>, <0, 0, 1> } }
  texture { object { torus { 1, 0.4 rotate 90*x }
              texture { pigment { rgb <0.2, 0.4, 1> } finish { ambient 1 diffuse 0 } },
              texture { pigment { rgb <1, 1, 0.2> } finish { ambient 0.2 diffuse 0.8 } } }
            scale 1.2 translate <-2, -1.5, 0> } }
sphere { <2, -1.5, 0>, 1.4
  pigment { rgb 0.8 } finish { ambient 0.1 diffuse 0.9 }
  normal { object { box { <-0.5, -2, -2>, <0.5, 2, 2> } normal { bumps 0.8 scale 0.1 }, normal { gradient x 2 } }
           translate <2, -1.5, 0> } }
