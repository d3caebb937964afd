// Declared objects are reused with `object`, and modifiers apply to the copy.
#declare Ball = sphere { <0, 1, 0>, 0.5 }
object { Ball }
object { Ball translate <2, 0, 0> }
