// Negative and fractional steps; 0 to 0.3 by 0.1 runs 4 times despite rounding.
#for (K, 5, 1, -2)
  sphere { <K, 0, 0>, 0.5 }
#end
#declare N = 0;
#for (F, 0, 0.3, 0.1)
  #declare N = N + 1;
#end
sphere { <0, N, 0>, 0.25 }
