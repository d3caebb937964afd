// Scoping is dynamic: a macro sees its caller's #locals, and #declare changes the innermost
// existing binding (the caller's local), leaving the global of the same name alone.
#declare L = 1;
#macro Inner()
  #declare Seen = L;
  #declare L = 8;
#end
#macro Outer()
  #local L = 4;
  Inner()
  #declare After = L;
#end
Outer()
sphere { <L, Seen, After>, 0.5 }
