// Indexing past the end of an array.
#declare A = array[3] {1, 2, 3};
sphere { <0, 0, 0>, A[3] }
