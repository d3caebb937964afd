mesh { triangle { 0, x, y } sphere { 0, 1 } }
