// The amount: the default (0.5), the number after the pattern, bump_size, a negative amount,
// the last one written winning, and accuracy (a wider sampling of a curved value).
#include "common.inc"
Ball(0, 0, normal { gradient x sine_wave scale 0.3 })
Ball(1, 0, normal { gradient x 2 sine_wave scale 0.3 })
Ball(2, 0, normal { gradient x sine_wave scale 0.3 bump_size 1.3 })
Ball(0, 1, normal { gradient x -2 sine_wave scale 0.3 })
Ball(1, 1, normal { gradient x 4 sine_wave scale 0.3 bump_size 0.7 accuracy 0.2 })
Ball(2, 1, normal { gradient x 2 sine_wave scale 0.3 accuracy 0.005 })
