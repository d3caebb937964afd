// More noise normals: cells, spotted, spiral1 and 2, a warp's turbulence, noise_generator 1.
#include "common.inc"
Ball(0, 0, normal { cells 1 scale 0.15 })
Ball(1, 0, normal { spotted 2 scale 0.2 noise_generator 1 })
Ball(2, 0, normal { spiral1 5 2 scale 0.2 })
Ball(0, 1, normal { spiral2 3 1 scale 0.3 })
Ball(1, 1, normal { gradient x 2 sine_wave scale 0.2 warp { turbulence 0.3 } })
Ball(2, 1, normal { bumps 1 turbulence 0.4 scale 0.2 })
