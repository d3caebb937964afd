// An isosurface and a function pattern: the compiled function's size, the container and the
// search settings (accuracy and max_gradient at or below 0 are warned about and reset).
#include "functions.inc"
isosurface {
  function { f_torus(x, y, z, 0.8, 0.2) + x / 4 }
  contained_by { sphere { <0, 0.1, 0>, 1.2 } }
  threshold 0.05 accuracy 0 max_gradient 3 evaluate 1, 2, 0.9 open max_trace 3
  pigment { function { abs(x) } }
  translate y
}
isosurface { function { y } all_intersections }
