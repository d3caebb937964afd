// `optional` parameters may be left out; #ifdef tells whether one was given.
#macro Ball(C, optional R)
  #ifdef (R)
    sphere { C, R }
  #else
    sphere { C, 0.125 }
  #end
#end
Ball(<1, 0, 0>, 2)
Ball(<2, 0, 0>)
