// Reading an array element that was never set.
#declare A = array[3];
#declare A[0] = 1;
sphere { <0, 0, 0>, A[1] }
