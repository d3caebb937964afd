// A partial rainbow arc: arc_angle, with falloff_angle given (it defaults to arc_angle).
rainbow { angle 42 width 5 arc_angle 120 falloff_angle 40 colour_map { [0 rgb 1] [1 rgb 0] } }
