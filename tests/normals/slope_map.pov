// slope_map: heights and slopes between the keys (a cubic through both), a single entry, keys
// out of order, and a slope_map replaced by a later normal_map (and the other way round).
#include "common.inc"
Ball(0, 0, normal { gradient x 2 scale 0.5 slope_map { [0 <0, 1>] [0.5 <1, 0>] [1 <0, -1>] } })
Ball(1, 0, normal { onion 3 translate <0.4, 0.3, -0.6> scale 0.4
                    slope_map { [0 <0, 0>] [0.3 <1, 2>] [0.6 <0.5, -1>] [1 <0, 0>] } })
Ball(2, 0, normal { gradient y 3 scale 0.4 slope_map { [0.5 <0.5, 0>] } })
Ball(0, 1, normal { gradient x 2 scale 0.4 slope_map { [0.8 <0, 1>] [0.2 <1, 0>] [0.5 <0.2, 3>] } })
Ball(1, 1, normal { gradient x 3 scale 0.4 slope_map { [0 <0, 1>] [1 <1, 1>] }
                    normal_map { [0 gradient y 2 sine_wave scale 0.2] [1 gradient y 2 scale 0.2] } })
Ball(2, 1, normal { gradient x 3 scale 0.4
                    normal_map { [0 gradient y 2 sine_wave scale 0.2] [1 gradient y 2 scale 0.2] }
                    slope_map { [0 <0, 1>] [0.5 <1, -1>] [1 <0, 1>] } })
