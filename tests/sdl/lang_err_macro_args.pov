// Calling a macro with too many arguments.
#macro Ball(C, R) sphere { C, R } #end
Ball(<0, 0, 0>, 1, 2)
