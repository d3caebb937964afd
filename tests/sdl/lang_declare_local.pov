// #declare and #local at the top level of the main file both make globals.
#declare A = 1;
#local B = 2;
#declare C = A + B;
#declare A = 10;  // redeclaring replaces the value
sphere { <A, B, C>, 0.5 }
