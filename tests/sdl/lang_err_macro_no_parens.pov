// A macro name needs an argument list.
#macro Size() 2 #end
sphere { <0, 0, 0>, Size }
