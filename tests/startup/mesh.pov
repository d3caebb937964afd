// A mesh of N x N squares (two triangles each), for the start-up tests: lumen traces meshes of
// 256 triangles and more through Embree, and opens it for them. mesh_small.pov: fewer.
#version 3.7;
#ifndef (N) #declare N = 12; #end
camera { location <0.5, 0.5, -2> look_at <0.5, 0.5, 0> }
light_source { <2, 4, -3> rgb 1 }
mesh {
  #for (i, 0, N - 1) #for (j, 0, N - 1)
    triangle { <i, j, 0> / N, <i + 1, j, 0> / N, <i + 1, j + 1, 0> / N }
    triangle { <i, j, 0> / N, <i + 1, j + 1, 0> / N, <i, j + 1, 0> / N }
  #end #end
  pigment { rgb 1 }
}
