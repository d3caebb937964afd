// Wrong number of arguments to a built-in function.
sphere { <0, 0, 0>, sqrt(4, 9) }
