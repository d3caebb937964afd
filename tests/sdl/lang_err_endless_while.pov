// An endless loop ends at the default per-loop limit (interp/budget.hpp), in well under a second.
#declare N = 0;
#while (1)
  #declare N = N + 1;
#end
