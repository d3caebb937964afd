// List forms: each block of checker, brick, hexagon, square and triangular takes its own
// normal, without blending across the edges.
#include "common.inc"
Ball(0, 0, normal { checker normal { gradient x 3 sine_wave scale 0.1 }
                            normal { gradient y 3 sine_wave scale 0.1 } scale 0.4 })
Ball(1, 0, normal { brick normal { onion 2 sine_wave scale 0.05 } normal { gradient x 2 sine_wave scale 0.1 }
                    brick_size <0.6, 0.25, 0.4> mortar 0.06 })
Ball(2, 0, normal { hexagon normal { gradient x 3 sine_wave scale 0.1 }
                            normal { gradient y 3 sine_wave scale 0.1 }
                            normal { gradient x -3 sine_wave scale 0.1 } scale 0.25 rotate -90*x })
Ball(0, 1, normal { square normal { gradient x 3 sine_wave scale 0.1 }
                           normal { gradient y 3 sine_wave scale 0.1 }
                           normal { gradient x -3 sine_wave scale 0.1 }
                           normal { gradient y -3 sine_wave scale 0.1 } scale 0.3 rotate -90*x })
Ball(1, 1, normal { triangular normal { gradient x 3 sine_wave scale 0.1 }
                               normal { gradient y 3 sine_wave scale 0.1 }
                               normal { gradient x -3 sine_wave scale 0.1 }
                               normal { gradient y -3 sine_wave scale 0.1 }
                               normal { onion 3 sine_wave scale 0.1 }
                               normal { gradient z 3 sine_wave scale 0.1 } scale 0.3 rotate -90*x })
Ball(2, 1, normal { checker normal { gradient x 3 sine_wave scale 0.1 } normal { checker 2 scale 0.1 }
                    scale 0.5 })
