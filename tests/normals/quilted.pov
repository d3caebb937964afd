// quilted: the default controls, a straight seam, S curves, large controls, a non-uniform
// scale and no_bump_scale.
#include "common.inc"
Ball(0, 0, normal { quilted scale 0.3 })
Ball(1, 0, normal { quilted 2 control0 0 control1 0 scale 0.3 })
Ball(2, 0, normal { quilted 1.5 control0 0.3 control1 0.8 scale 0.25 rotate <20, 30, 0> })
Ball(0, 1, normal { quilted 1 control0 2 control1 -1 scale 0.3 })
Ball(1, 1, normal { quilted 2 scale <0.2, 0.4, 0.3> })
Ball(2, 1, normal { quilted 0.5 scale 0.3 no_bump_scale })
