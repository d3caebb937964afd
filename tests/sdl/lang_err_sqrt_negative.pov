// POV-Ray stops with "sqrt of negative number" (interp/math_builtins.cpp).
#declare R = sqrt(-4);
sphere { 0, R }
