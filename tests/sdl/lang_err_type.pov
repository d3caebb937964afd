// A string where a float is needed.
#declare Name = "ball";
sphere { <0, 0, 0>, Name * 2 }
