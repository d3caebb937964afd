// A value is true when |v| > 1e-10: a tiny number is false.
#if (1e-11)
  sphere { <1, 0, 0>, 1 }
#else
  sphere { <2, 0, 0>, 1.5 }
#end
#if (0.5 & 2)
  sphere { <3, 0, 0>, 1.5 }
#end
#if (0 | -1)
  sphere { <4, 0, 0>, 1.5 }
#end
