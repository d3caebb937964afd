// Two-dimensional arrays are row-major: Grid[row][column].
#declare Grid = array[2][3] {
  {1, 2, 3},
  {4, 5, 6}
}
sphere { <Grid[0][2], Grid[1][0], dimensions(Grid)>, Grid[1][2] / 4 }
