// average: the normal_map's normals weighted by their values (1 when left out).
#include "common.inc"
Ball(0, 0, normal { average normal_map { [gradient x 3 sine_wave scale 0.2] [gradient y 3 sine_wave scale 0.2] } })
Ball(1, 0, normal { average normal_map { [3 gradient x 3 sine_wave scale 0.2] [1 gradient y 3 sine_wave scale 0.2] } })
Ball(2, 0, normal { average normal_map { [1 gradient x 3 triangle_wave scale 0.2]
                                         [0.5 onion 2 sine_wave scale 0.1]
                                         [2 cylindrical 2 scale 0.3] } scale <1, 0.7, 1> })
Ball(0, 1, normal { average normal_map { [gradient x -4 scallop_wave scale 0.3] [gradient y -4 scallop_wave scale 0.3] } })
Ball(1, 1, normal { average normal_map { [1 gradient x 3 sine_wave scale 0.2] [1 quilted 1 scale 0.2] } rotate 30*z })
Ball(2, 1, normal { average normal_map { [2 gradient x 3 sine_wave scale 0.2] } })
