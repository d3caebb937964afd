// Normals: the pattern, the amount and accuracy (single precision, as POV keeps them),
// no_bump_scale, slope_map and list entries are recorded; a normal lumen does not render yet
// is listed as unsupported.
sphere { 0, 1 normal { bumps 0.4 scale 0.2 } }
sphere { 0, 1 normal { gradient x bump_size 2 accuracy 0.05 no_bump_scale
                       slope_map { [0 <0, 1>] [1 <1, 0>] } } }
sphere { 0, 1 normal { checker normal { quilted } normal { pavement } } }
