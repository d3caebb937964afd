// Parameters are new locals: a global with the same name is not changed, and #local inside
// the macro disappears when it returns. A #declare of a new name inside is global.
#declare P = 100;
#macro M(P)
  #local Temp = P * 2;
  #declare Made = Temp + 1;
#end
M(3)
#ifdef (Temp)
  sphere { <0, 0, 0>, 9 }
#end
sphere { <P, Made, 0>, 0.5 }
