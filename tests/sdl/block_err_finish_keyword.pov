sphere { 0, 1
  finish { phong 0.5 checker }
}
