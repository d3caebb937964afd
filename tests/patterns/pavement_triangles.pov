// pavement with triangular cells (number_of_sides 3, POV-Ray's default) viewed from above the
// x-z plane: every layout of 1-6 tiles, panels of 1 x 0.8, each another exterior / interior /
// form setting (the corners' and bends' shapes), some panels rotated and the last row moved
// far out; nudged off the cell lines, where the renderers may break ties between cells apart.
// The first panel is the bare default `pavement`.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> direction z right 5*x up 4*y }
#declare F = finish { ambient 1 diffuse 0 }
#declare Ramp = color_map { [0 rgb <0.1, 0, 0.3>] [0.3 rgb <1, 0.3, 0>] [0.6 rgb <1, 1, 0.4>] [1 rgb <0.2, 0.6, 1>] }
#declare Up = transform { rotate -90 * x }  // the pattern's x-z plane faces the camera
#declare Nudge = transform { scale 0.12 translate <0.0123, 0, 0.0371> }
#macro Panel(T, N, Col, Row, E, I, Fo, R)
  box { <-2.5 + Col, 1.2 - 0.8 * Row, 0>, <-1.5 + Col, 2 - 0.8 * Row, 1>
    pigment { pavement number_of_sides 3 number_of_tiles T pattern N exterior E interior I form Fo
      color_map { Ramp } transform { Nudge } rotate R * y
      translate <1000.3, 0, -77.7> * (Row = 4) transform { Up } }
    finish { F } }
#end
box { <-2.5, 1.2, 0>, <-1.5, 2, 1>
  pigment { pavement color_map { Ramp } transform { Nudge } transform { Up } } finish { F } }
Panel(1, 1, 1, 0, 1, 0, 0, 0)
Panel(1, 1, 2, 0, 2, 0, 0, 15)
Panel(2, 1, 3, 0, 0, 0, 1, 0)
Panel(2, 1, 4, 0, 1, 1, 2, 0)
Panel(3, 1, 0, 1, 2, 1, 0, 0)
Panel(4, 1, 1, 1, 0, 2, 1, 0)
Panel(4, 2, 2, 1, 1, 0, 2, -20)
Panel(4, 3, 3, 1, 2, 2, 3, 0)
Panel(5, 1, 4, 1, 0, 1, 2, 0)
Panel(5, 2, 0, 2, 1, 2, 1, 0)
Panel(5, 3, 1, 2, 0, 0, 0, 0)
Panel(5, 4, 2, 2, 2, 0, 2, 30)
Panel(6, 1, 3, 2, 1, 1, 1, 0)
Panel(6, 2, 4, 2, 0, 2, 0, 0)
Panel(6, 3, 0, 3, 2, 1, 2, 0)
Panel(6, 4, 1, 3, 0, 0, 1, 45)
Panel(6, 5, 2, 3, 1, 2, 0, 0)
Panel(6, 6, 3, 3, 2, 0, 1, 0)
Panel(6, 7, 4, 3, 0, 1, 2, 0)
Panel(6, 8, 0, 4, 1, 0, 3, 0)
Panel(6, 9, 1, 4, 2, 2, 1, 0)
Panel(6, 10, 2, 4, 0, 1, 1, 0)
Panel(6, 11, 3, 4, 1, 2, 2, -10)
Panel(6, 12, 4, 4, 2, 1, 0, 0)
