// select(a, b, c[, d]) by the sign of a; min and max take any number of arguments.
sphere { <select(-1, 1, 2, 3), select(0, 1, 2, 3), select(1, 1, 2, 3)>, select(0, 0.25, 0.5) }
sphere { <min(3, 1, 2), max(3, 1, 2), max(-1, -5)>, min(0.5, 2) }
