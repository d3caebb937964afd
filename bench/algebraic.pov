// Render benchmark of the algebraic shapes (bench/render_vs_povray.sh bench/algebraic.pov):
// rows of quartic tori (closed form and sturm), a sextic poly (always the Sturm search),
// superellipsoids and quadrics, with a reflective floor so every shape is traced twice.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -11> look_at <0, 0.5, 0> angle 55 }
light_source { <-8, 12, -10> rgb 1 }
light_source { <6, 8, -4> rgb 0.5 }
background { rgb <0.2, 0.25, 0.35> }
plane { y, -1 pigment { checker rgb 0.8 rgb 0.4 } finish { reflection 0.3 } }
#declare Torus4 = quartic {
  < 1, 0, 0, 0, 2, 0, 0, 2, 0, -2.32,  0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    1, 0, 0, 2, 0, 1.68, 0, 0, 0, 0,  1, 0, -2.32, 0, 0.7056 >
}
#for (I, 0, 4)
  object { Torus4 pigment { rgb <1, 0.5, 0.3> } finish { phong 0.6 } rotate <60, 25 * I, 0> translate <-5 + 2.5 * I, 0.2, 2> }
  object { Torus4 sturm pigment { rgb <0.4, 0.8, 0.5> } finish { phong 0.6 } rotate <-30, 40 * I, 0> translate <-5 + 2.5 * I, 0.2, -0.5> }
  superellipsoid { <0.2 + 0.4 * I, 0.3 + 0.3 * I> pigment { rgb <0.4, 0.6, 1> } finish { phong 0.6 }
    rotate <20, 30 * I, 0> translate <-5 + 2.5 * I, 0.1, -3> }
#end
// x^6 + y^6 + z^6 = 0.4 and a hyperboloid, in the back.
poly { 6, <
    1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, -0.4 >
  pigment { rgb <1, 0.9, 0.4> } finish { phong 0.6 } scale 1.2 translate <-2.5, 0.5, 5> }
quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, -0.3 clipped_by { box { -1.5, 1.5 } }
  pigment { rgb <0.8, 0.5, 0.9> } finish { phong 0.6 } translate <2.5, 0.6, 5> }
