// A partial rainbow arc (arc_angle, falloff_angle) is not built: a located unsupported feature.
rainbow { angle 42 width 5 arc_angle 120 colour_map { [0 rgb 1] [1 rgb 0] } }
