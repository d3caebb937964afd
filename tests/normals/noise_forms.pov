// The vector-noise normals: bumps (amounts, scales, no_bump_scale, the generator not used) and
// wrinkles (ten octaves of the noise's absolute value, leaning towards +x+y+z).
#include "common.inc"
Ball(0, 0, normal { bumps 0.8 scale 0.15 })
Ball(1, 0, normal { bumps 1.5 scale <0.1, 0.3, 0.2> rotate 20*z })
Ball(2, 0, normal { bumps 0.1 scale 0.1 no_bump_scale noise_generator 3 })
Ball(0, 1, normal { wrinkles 1 scale 0.3 })
Ball(1, 1, normal { wrinkles 2.5 scale <0.5, 0.2, 0.3> })
Ball(2, 1, normal { bumps 0.6 scale 0.2 bump_size 2 accuracy 0.5 })
