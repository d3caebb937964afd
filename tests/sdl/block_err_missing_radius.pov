sphere { <0, 1, 0> }
