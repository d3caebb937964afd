// The value of a #declare may come from a directive, as in POV-Ray's sample scenes.
#declare Simple = 0;
#declare Shape =
#if (Simple)
  sphere { <1, 0, 0>, 1 }
#else
  sphere { <2, 0, 0>, 2 }
#end
object { Shape }
