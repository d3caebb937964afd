// The normal's transforms: a uniform scale leaves the tilt as it is, a non-uniform one tilts
// it, no_bump_scale makes smaller patterns tilt more; the object's own transforms move it.
#include "common.inc"
Ball(0, 0, normal { cylindrical 2 sine_wave frequency 3 scale 0.9 })
Ball(1, 0, normal { cylindrical 2 sine_wave frequency 3 scale <0.5, 1, 1.2> rotate 40*z })
Ball(2, 0, normal { cylindrical 1 sine_wave frequency 3 scale 0.9 no_bump_scale })
Ball(0, 1, normal { cylindrical 1 sine_wave frequency 3 scale <0.5, 1, 1.2> rotate 40*z no_bump_scale })
sphere { 0, 0.66
  texture { Matte normal { gradient y 3 sine_wave scale 0.2 } }
  scale <1, 0.6, 1> rotate 30*z translate <0, -0.73, 0> }
sphere { 0, 0.66
  texture { Matte normal { gradient y 0.5 sine_wave scale 0.2 no_bump_scale } }
  scale <0.8, 1, 1> rotate -20*z translate <1.35, -0.73, 0> }
