camera { location <0, 2, -5> look_at <0, 1, 0> }
