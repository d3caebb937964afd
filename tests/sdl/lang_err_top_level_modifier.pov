// A modifier standing alone at top level.
sphere { <0, 0, 0>, 1 }
translate <1, 0, 0>
