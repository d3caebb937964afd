union {
  sphere { 0, 1 }
  translate x
  sphere { x, 1 }
}
