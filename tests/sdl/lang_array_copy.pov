// #declare B = A copies an array; changing B leaves A alone.
#declare A = array[2] {1, 2};
#declare B = A;
#declare B[0] = 10;
sphere { <A[0], B[0], A[1]>, 0.5 }
