// normal_map: the entries around the pattern's value are blended; each is evaluated in the
// parent's pattern space (the parent's scale moves the entries), the parent's amount and
// accuracy are ignored; maps nest.
#include "common.inc"
Ball(0, 0, normal { gradient x normal_map { [0 gradient y 3 sine_wave scale 0.2]
                                          [1 onion 2 sine_wave scale 0.15] } scale 0.8 })
Ball(1, 0, normal { gradient x 5 accuracy 0.3 normal_map { [0 gradient y 3 sine_wave scale 0.2]
                                                         [1 onion 2 sine_wave scale 0.15] } })
Ball(2, 0, normal { gradient y normal_map { [0.2 gradient x 3 triangle_wave scale 0.15]
                                          [0.4 radial 2 frequency 10 scallop_wave]
                                          [0.8 gradient x -3 triangle_wave scale 0.15] }
                    scale <0.8, 1.2, 1> translate -0.5*y })
Ball(0, 1, normal { spherical scale 0.7
                    normal_map { [0 gradient x 3 sine_wave scale 0.2]
                                 [1 gradient y normal_map { [0 onion 3 sine_wave scale 0.1]
                                                            [1 gradient z 2 sine_wave scale 0.1] }] } })
Ball(1, 1, normal { gradient x normal_map { [0 gradient y 3 sine_wave scale 0.2 no_bump_scale]
                                          [1 gradient y 3 sine_wave scale <0.1, 0.3, 1>] }
                    scale <1, 0.5, 1> })
Ball(2, 1, normal { onion frequency 3 sine_wave
                    normal_map { [0 boxed 3 scale 0.3] [0.5 gradient y 2 sine_wave scale 0.1]
                                 [1 cylindrical 2 scale 0.4] } })
