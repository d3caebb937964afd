// uv_mapping: textures laid onto a surface's own (u, v) instead of space. A globe of
// longitude and latitude bands, a die whose faces are cells of one unfolded cross, a striped
// ring, a vase (sor) and a goblet (lathe) banded along their profiles, and a mesh2 tile whose
// checker follows its uv_vectors. The object transforms move the shapes, never the textures.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 4.5, -9>
  look_at  <0, 0.9, 0>
  right x*image_width/image_height
  angle 50
}

light_source { <-6, 10, -8> color rgb 1 }
light_source { <6, 6, -6> color rgb 0.35 shadowless }
background { color rgb <0.18, 0.22, 0.28> }

#default { finish { ambient 0.15 diffuse 0.8 specular 0.2 } }

plane { y, 0 pigment { checker rgb <0.75, 0.72, 0.66>, rgb <0.6, 0.58, 0.53> } }

// The globe: 12 longitude by 6 latitude cells, tilted on its axis.
sphere { 0, 1
  uv_mapping
  pigment { checker rgb <0.15, 0.35, 0.8>, rgb <0.9, 0.85, 0.4> scale <1/12, 1/6, 1> }
  rotate <0, 30, -23> translate <-3, 1, 1> }

// The die: the cross layout gives each face a 1/4 x 1/3 cell; a gradient per direction.
box { -0.7, 0.7
  pigment { uv_mapping average pigment_map {
    [1 gradient x colour_map { [0 rgb <0.1, 0, 0.5>] [1 rgb <1.9, 0, 0.5>] }]
    [1 gradient y colour_map { [0 rgb <0, 0.1, 0.3>] [1 rgb <0, 1.9, 0.3>] }] } }
  rotate <15, 35, 0> translate <-0.6, 0.9, 1.2> }

// The ring: bands around the tube and along it.
torus { 0.75, 0.28
  texture { uv_mapping pigment { checker rgb <0.9, 0.3, 0.2>, rgb 0.95 scale <1/16, 1/4, 1> } }
  rotate -55 * x translate <1.6, 1.05, 1.2> }

// The vase: stripes around it, bands up its sides, rings on the base and the cap.
sor { 7, <0, -0.1>, <0.45, 0>, <0.7, 0.5>, <0.35, 1.1>, <0.28, 1.4>, <0.45, 1.7>, <0.5, 1.8>
  pigment { uv_mapping checker rgb <0.3, 0.7, 0.4>, rgb <0.95, 0.9, 0.8> scale <1/10, 1/8, 1> }
  translate <3.6, 0, 1.6> }

// The goblet: a cubic profile; v runs along the spline segments.
lathe { cubic_spline 7, <0, 0>, <0.5, 0>, <0.2, 0.3>, <0.12, 0.9>, <0.55, 1.2>, <0.6, 1.7>, <0.5, 1.8>
  pigment { uv_mapping gradient y colour_map { [0 rgb <0.5, 0.1, 0.6>] [0.5 rgb <1, 0.7, 0.2>] [1 rgb <0.5, 0.1, 0.6>] } }
  translate <-2.2, 0, -1.9> }

// The tile: a mesh2 whose uv_vectors skew the checker across its two triangles.
mesh2 {
  vertex_vectors { 4, <-1, 0, -1>, <1, 0, -1>, <1, 0, 1>, <-1, 0, 1> }
  uv_vectors { 4, <0, 0>, <4, 0.5>, <4.5, 4>, <0, 3.5> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
  uv_mapping
  pigment { checker rgb <0.1, 0.1, 0.12>, rgb <0.95, 0.95, 0.9> }
  scale 0.8 rotate 20 * y translate <1.2, 0.02, -1.6> }
