sphere { 0, 1
  pigment {
    radial frequency 4
    pigment_map {
      [0.0 rgb <1, 0, 0>]
      [0.5 checker rgb 1, rgb 0 scale 0.1]
      [1.0 spherical]
    }
  }
}
