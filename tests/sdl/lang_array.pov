// One-dimensional arrays: initialiser, element assignment, loops over dimension_size.
#declare Radii = array[3] {0.5, 1, 1.5};
#declare Radii[1] = Radii[0] + Radii[2];
#for (I, 0, dimension_size(Radii, 1) - 1)
  sphere { <I, 0, 0>, Radii[I] }
#end
