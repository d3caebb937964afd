sphere { 0, 1
  pigment {
    gradient <0, 2, 0>
    color_map { [0.0 rgb 0] [0.5 rgb <1, 0, 0>] [0.5 rgb <0, 1, 0>] [1.0 rgb 1] }
    frequency 2 phase 0.25 triangle_wave
    scale 3
  }
}
// The old band form [a b colour1 colour2], and a declared map.
#declare M = color_map { [0 0.5 color rgb 1 color rgb 0] }
sphere { 0, 1 pigment { onion color_map { M } poly_wave 2 } }
