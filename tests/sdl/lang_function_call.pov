// User-defined functions can be called in expressions; without a parameter list the
// parameters are x, y and z.
#declare Scale = function(a, b) { a * 2 + b }
#declare Mix = function { x + y * z }
sphere { <Scale(3, 4), Mix(1, 2, 3), Scale(Mix(0, 1, 1), 0)>, 0.5 }
