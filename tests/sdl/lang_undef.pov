// #undef removes a declaration; #ifdef / #ifndef see it gone.
#declare Size = 2;
#undef Size
#ifdef (Size)
  sphere { <1, 0, 0>, Size }
#else
  sphere { <0, 1, 0>, 0.25 }
#end
#ifndef (Size)
  sphere { <0, 0, 1>, 0.75 }
#end
