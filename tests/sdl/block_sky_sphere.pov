sky_sphere {
  pigment { gradient y color_map { [0 rgb <0.8, 0.8, 1>] [1 rgb <0.1, 0.2, 0.8>] } }
  pigment { rgbt 1 }
  rotate x*-10
  emission 0.8
}
