// Every finite and infinite primitive: sphere, plane, box, cylinder, cone, torus, disc,
// triangle, smooth_triangle, polygon, mesh and mesh2.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 6, -9>
  look_at  <0, 0.5, 0>
  right x*image_width/image_height
  angle 55
}

light_source { <-6, 10, -8> color rgb 1 }
light_source { <6, 6, -6> color rgb 0.4 }
background { color rgb <0.2, 0.25, 0.3> }

#default { finish { ambient 0.1 diffuse 0.8 specular 0.3 } }

plane { y, 0 pigment { color rgb <0.7, 0.7, 0.65> } }

// back row
sphere   { <-3.6, 0.7, 2.5>, 0.7 pigment { color rgb <1, 0.2, 0.2> } }
box      { <-2.0, 0, 1.9>, <-0.8, 1.2, 3.1> pigment { color rgb <0.2, 1, 0.2> } }
cylinder { <0.6, 0, 2.5>, <0.6, 1.4, 2.5>, 0.55 pigment { color rgb <0.2, 0.4, 1> } }
cone     { <2.3, 0, 2.5>, 0.7, <2.3, 1.5, 2.5>, 0.1 pigment { color rgb <1, 1, 0.2> } }
torus    { 0.6, 0.2 translate <3.9, 0.2, 2.5> pigment { color rgb <1, 0.3, 1> } }

// front row
disc     { <-3.6, 0.01, -0.2>, y, 0.7, 0.3 pigment { color rgb <0.2, 1, 1> } }
triangle { <-2.4, 0, -0.6>, <-1.0, 0, -0.6>, <-1.7, 1.3, 0> pigment { color rgb <1, 0.6, 0.1> } }
smooth_triangle {
  <-0.6, 0, -0.6>, <-0.5, 0, -1>,
  < 0.8, 0, -0.6>, < 0.5, 0, -1>,
  < 0.1, 1.3, 0>,  <0, 0.5, -1>
  pigment { color rgb <0.6, 0.3, 1> }
}
polygon {
  5, <1.2, 0, -0.3>, <2.4, 0, -0.3>, <2.4, 1.0, -0.3>, <1.8, 1.5, -0.3>, <1.2, 1.0, -0.3>
  pigment { color rgb <0.9, 0.9, 0.9> }
}
// a square pyramid as a mesh
mesh {
  triangle { <-0.5, 0, -0.5>, < 0.5, 0, -0.5>, <0, 1, 0> }
  triangle { < 0.5, 0, -0.5>, < 0.5, 0,  0.5>, <0, 1, 0> }
  triangle { < 0.5, 0,  0.5>, <-0.5, 0,  0.5>, <0, 1, 0> }
  triangle { <-0.5, 0,  0.5>, <-0.5, 0, -0.5>, <0, 1, 0> }
  translate <3.4, 0, -0.3>
  pigment { color rgb <1, 0.5, 0.5> }
}
// a tetrahedron as a mesh2
mesh2 {
  vertex_vectors { 4, <-0.6, 0, -0.4>, <0.6, 0, -0.4>, <0, 0, 0.6>, <0, 1.1, 0> }
  face_indices { 4, <0, 1, 3>, <1, 2, 3>, <2, 0, 3>, <0, 2, 1> }
  translate <0, 0, -2.6>
  pigment { color rgb <0.5, 1, 0.5> }
}
