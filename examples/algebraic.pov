// Algebraic shapes solved by POV-Ray's polynomial solver: a quartic torus and a lemniscate-
// like quartic (poly), a cubic saddle clipped to a box, superellipsoids from cushion to star,
// and a quadric paraboloid bowl.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 4, -9>
  look_at  <0, 0.8, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-6, 12, -8> color rgb 1 }
light_source { <7, 4, -6> color rgb 0.35 }
background { color rgb <0.2, 0.22, 0.3> }

plane { y, -0.01
  pigment { checker color rgb 0.7 color rgb 0.45 }
  finish { reflection 0.12 }
}
#declare Shiny = finish { phong 0.8 phong_size 80 reflection 0.1 }

// A torus as a quartic: (x^2+y^2+z^2+R^2-r^2)^2 - 4R^2(x^2+z^2), R = 0.9, r = 0.3.
#declare R = 0.9; #declare r = 0.3;
#declare K = R * R - r * r;
quartic {
  < 1, 0, 0, 0, 2, 0, 0, 2, 0, 2 * K - 4 * R * R,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    1, 0, 0, 2, 0, 2 * K, 0, 0, 0, 0,
    1, 0, 2 * K - 4 * R * R, 0, K * K >
  sturm
  pigment { color rgb <0.95, 0.6, 0.2> }
  finish { Shiny }
  rotate <60, 20, 0>
  translate <-2.8, 1.2, 0.5>
}

// A cubic saddle z = x^3 - 3xy^2 (the monkey saddle), clipped to a box.
intersection {
  cubic { < 1, 0, 0, 0, -3, 0, 0, 0, 0, 0,  0, 0, 0, 0, 0, 0, 0, 0, -1, 0 > }
  box { <-0.8, -0.8, -0.8>, <0.8, 0.8, 0.8> }
  pigment { color rgb <0.3, 0.75, 0.95> }
  finish { Shiny }
  rotate -90 * x
  translate <0, 1.0, 0.6>
}

// Superellipsoids, from a rounded cube to a star.
#declare Shapes = array[4] { <0.2, 0.2>, <1, 0.3>, <2, 2>, <3, 0.6> }
#for (I, 0, 3)
  superellipsoid { Shapes[I]
    pigment { color rgb <0.5 + I * 0.15, 0.9 - I * 0.15, 0.5> }
    finish { Shiny }
    scale 0.45
    rotate <-20, 30, 0>
    translate <-1.8 + I * 1.2, 0.46, -2.2>
  }
#end

// A paraboloid bowl y = x^2 + z^2 (a quadric), cut at y = 0.8.
intersection {
  quadric { <1, 0, 1>, <0, 0, 0>, <0, -1, 0>, 0 }
  plane { y, 0.8 }
  pigment { color rgb <0.85, 0.35, 0.5> }
  finish { Shiny }
  scale 0.9
  translate <2.8, 0.02, 0.8>
}
