// Differenced normals of the continuous patterns lumen renders, with their wave types, on
// spheres.
#include "common.inc"
Ball(0, 0, normal { onion 3 sine_wave scale 0.3 translate <0.5, 0.4, -0.6> })
Ball(1, 0, normal { gradient <1, 1, 0> 4 triangle_wave scale 0.4 })
Ball(2, 0, normal { radial 2 frequency 8 scallop_wave rotate -70*x })
Ball(0, 1, normal { spherical 3 cubic_wave scale 0.6 translate <0.2, 0.3, -0.5> })
Ball(1, 1, normal { cylindrical 3 sine_wave frequency 3 phase 0.2 scale 0.5 rotate 30*x })
Ball(2, 1, normal { boxed 3 poly_wave 2 frequency 2 scale 0.5 rotate <20, 30, 0> })
