// facets (the amount does not count): without coords the normal snaps to the nearest cell
// point of the normal over size (the same facets on every sphere), with coords the cells of
// the point tilt it by coords times the tangent part of the vector noise; metric 1 (POV's
// signed sum, nearly a grid), 2.5 and the default 2.
#include "common.inc"
Ball(0, 0, normal { facets size 0.3 })
Ball(1, 0, normal { facets 3 size 0.2 metric 1 })
Ball(2, 0, normal { facets size 0.25 metric 2.5 scale <1, 2, 1> })
Ball(0, 1, normal { facets coords 0.5 })
Ball(1, 1, normal { facets coords 0.8 size 0.15 metric 1 rotate 30*z })
Ball(2, 1, normal { facets coords 1.5 size 0.3 metric 3 scale <0.5, 1, 1> })
