// rainbow { }: direction, angle, width, distance, jitter, up and the colour map; a declared
// rainbow reused and changed; defaults dumped only where changed.
#declare R = rainbow {
  angle 42.5 width 5 distance 1.0e7 direction <-0.2, -0.2, 1> jitter 0.01
  colour_map { [0 rgbf <1, 0.5, 1, 1>] [0.5 rgbf <0.2, 1, 0.2, 0.8>] [0.9 rgbf <1, 0.2, 0.2, 0.8>] }
}
rainbow { R }
rainbow { R angle 37 up z }
rainbow { colour_map { [0 rgb 1] [1 rgb 0] } }
