// Two sub-polygons (an outline and a hole), each closed by repeating its first point.
polygon { 10,
  <0, 0>, <4, 0>, <4, 4>, <0, 4>, <0, 0>,
  <1, 1>, <2, 1>, <2, 2>, <1, 2>, <1, 1>
}
// An unclosed list is closed with a warning.
polygon { 3, <0, 0, 1>, <1, 0, 1>, <0, 1, 1> }
