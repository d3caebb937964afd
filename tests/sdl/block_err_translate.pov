sphere { 0, 1
  translate "x"
}
