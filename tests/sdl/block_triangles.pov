triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
// Vertex normals are normalised.
smooth_triangle { <0, 0, 0>, <0, 0, -2>, <1, 0, 0>, <1, 0, -1>, <0, 1, 0>, <0, 3, -3> }
