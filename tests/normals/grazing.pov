// Degenerate normals: amounts large enough to turn the normal past the surface or away from
// the viewer, patterns whose slope is zero, and light from behind a bumped plane. No pixel may
// be NaN.
#include "common.inc"
Ball(0, 0, normal { gradient x 60 sine_wave scale 0.2 })
Ball(1, 0, normal { onion -80 sine_wave scale 0.3 translate <0, 0, 0.5> })
Ball(2, 0, normal { gradient z 1e6 scale 0.3 })
Ball(0, 1, normal { gradient x 0 scale 0.3 })
Ball(1, 1, normal { spherical 40 sine_wave scale 0.2 translate 0.3*z no_bump_scale })
plane { z, 0.2 texture { Matte normal { gradient x 50 sine_wave scale 0.3 } }
        clipped_by { box { <0.7, -1.5, -1>, <2, 0, 1> } } }
