// Differenced normals of the block patterns: only their edges, where the four samples
// straddle two blocks, tilt the normal.
#include "common.inc"
Ball(0, 0, normal { checker 2 scale 0.25 })
Ball(1, 0, normal { brick 3 brick_size <0.5, 0.2, 0.3> mortar 0.05 })
Ball(2, 0, normal { hexagon 2 scale 0.2 rotate -90*x })
Ball(0, 1, normal { square 2 scale 0.3 rotate -90*x })
Ball(1, 1, normal { triangular 2 scale 0.3 rotate -90*x accuracy 0.05 })
Ball(2, 1, normal { checker -3 scale 0.3 accuracy 0.1 })
