// dents (its magnitude from the generator), ripples and waves (POV's ten wave sources, the
// frequency and phase inside the wave).
#include "common.inc"
Ball(0, 0, normal { dents 3 scale 0.2 })
Ball(1, 0, normal { dents 4 scale 0.2 noise_generator 3 })
Ball(2, 0, normal { ripples 5 scale 0.1 })
Ball(0, 1, normal { ripples 2 frequency 3 phase 0.3 scale 0.3 })
Ball(1, 1, normal { waves 2 frequency 2 phase 0.4 scale <0.2, 0.4, 0.3> })
Ball(2, 1, normal { waves 6 frequency 0.5 scale 0.05 })
