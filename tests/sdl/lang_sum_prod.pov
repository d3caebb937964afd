// sum() and prod() evaluate an expression for each integer step of a variable.
sphere { <sum(I, 1, 4, I * I), prod(I, 1, 4, I), 0>, 0.5 }
