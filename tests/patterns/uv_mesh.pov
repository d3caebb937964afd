// uv_mapping on meshes: mesh2 with uv_indices, with one uv per vertex, with a single uv, and a
// mesh of triangles with and without uv_vectors.
#include "uv_common.inc"
mesh2 {
  vertex_vectors { 4, <-1, -1, 0>, <1, -1, 0>, <1, 1, 0>, <-1, 1, 0> }
  uv_vectors { 3, <0, 0>, <0.9, 0.1>, <0.4, 0.95> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
  uv_indices { 2, <0, 1, 2>, <0, 2, 1> }
  pigment { UvPigment } finish { UvFinish } scale 0.6 rotate 20 * z translate <-1.2, 0.6, 0> }
mesh2 {
  vertex_vectors { 4, <-1, -1, 0>, <1, -1, 0>, <1, 1, 0>, <-1, 1, 0> }
  uv_vectors { 4, <0.1, 0.1>, <0.8, 0>, <1, 0.7>, <0, 0.9> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
  uv_mapping pigment { UvColour scale 0.5 } finish { UvFinish } scale 0.6 rotate -15 * y translate <0.6, 0.6, 0> }
mesh2 {
  vertex_vectors { 3, <-1, -1, 0>, <1, -1, 0>, <0, 1, 0> }
  uv_vectors { 1, <0.3, 0.6> }
  face_indices { 1, <0, 1, 2> }
  pigment { UvPigment } finish { UvFinish } scale 0.4 translate <1.6, 0.8, 0> }
mesh {
  triangle { <-1, -1, 0>, <1, -1, 0>, <1, 1, 0> uv_vectors <0, 0>, <1, 0>, <0.5, 1> }
  triangle { <-1, -1, 0>, <1, 1, 0>, <-1, 1, 0> }
  pigment { UvPigment } finish { UvFinish } scale 0.7 translate <-0.5, -0.8, 0> }
