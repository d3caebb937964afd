// Macros are declared names too: #ifdef sees them, #undef removes them.
#macro Ball() sphere { <1, 1, 1>, 0.5 } #end
#ifdef (Ball)
  Ball()
#end
#undef Ball
#ifndef (Ball)
  sphere { <2, 2, 2>, 0.25 }
#end
