// The noise patterns as differenced normals: granite (with a wave and frequency), bozo (with
// accuracy and a slope_map), marble and wood with turbulence, agate, crackle, cells.
#include "common.inc"
Ball(0, 0, normal { granite 0.6 sine_wave frequency 2 scale 0.8 })
Ball(1, 0, normal { bozo 2 scale 0.2 accuracy 0.05 slope_map { [0 <0, 1>] [0.5 <1, 0>] [1 <0, -1>] } })
Ball(2, 0, normal { marble 2 turbulence 0.5 scale 0.5 })
Ball(0, 1, normal { wood 1.5 turbulence 0.2 scale 0.2 rotate 30*x })
Ball(1, 1, normal { agate 1 scale 0.3 })
Ball(2, 1, normal { crackle 2 scale 0.2 })
