mesh {
  triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
  smooth_triangle { <1, 0, 0>, <0, 0, -1>, <1, 1, 0>, <0, 0, -1>, <0, 1, 0>, <0, 0, -2>
    texture { pigment { rgb <1, 0, 0> } } }
  inside_vector z
  translate y
}
