box { -1, 1
  texture {
    planar
    texture_map {
      [0.2 pigment { rgb 1 } finish { phong 1 }]
      [0.8 pigment { rgb 0 }]
    }
    rotate x*90
  }
}
sphere { 0, 1 texture { checker texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } } }
