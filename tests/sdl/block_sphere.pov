// A sphere with transforms composed in the order written.
sphere { <1, 2, 3>, 0.5
  scale 2
  rotate z*90
  translate <0, 0, 1>
}
