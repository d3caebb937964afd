// #include runs another file in place: its #declares and macros are visible afterwards,
// its #locals are not, and the objects it makes join the scene.
#include "lang_include_defs.inc"
#ifdef (Hidden)
  sphere { <9, 9, 9>, 9 }
#end
Marker(Shared)
