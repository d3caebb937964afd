// pavement with hexagonal cells (number_of_sides 6) viewed from above the x-z plane: layouts of
// 1-5 tiles, each panel another exterior / interior / form setting (the convex corners' and
// the bends' shapes; exterior changes nothing for hexagons, form 3 draws as form 0), some
// panels rotated and one row moved far out; nudged off the cell lines, where the renderers may
// break ties between cells apart.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> direction z right 5*x up 4*y }
#declare F = finish { ambient 1 diffuse 0 }
#declare Ramp = color_map { [0 rgb <0.1, 0, 0.3>] [0.3 rgb <1, 0.3, 0>] [0.6 rgb <1, 1, 0.4>] [1 rgb <0.2, 0.6, 1>] }
#declare Up = transform { rotate -90 * x }  // the pattern's x-z plane faces the camera
#macro Panel(T, N, Col, Row, E, I, Fo, R)
  box { <-2.5 + Col, 1 - Row, 0>, <-1.5 + Col, 2 - Row, 1>
    pigment { pavement number_of_sides 6 number_of_tiles T pattern N exterior E interior I form Fo
      color_map { Ramp } scale 0.07 translate <0.0123, 0, 0.0371> rotate R * y
      translate <1000.3, 0, -77.7> * (Row = 3) transform { Up } }
    finish { F } }
#end
Panel(1, 1, 0, 0, 0, 0, 0, 0)
Panel(2, 1, 1, 0, 0, 1, 0, 0)
Panel(3, 1, 2, 0, 0, 2, 0, 10)
Panel(3, 2, 3, 0, 1, 1, 1, 0)
Panel(3, 3, 4, 0, 0, 0, 2, 0)
Panel(1, 1, 0, 1, 0, 0, 1, 0)
Panel(4, 1, 1, 1, 2, 2, 2, -20)
Panel(4, 2, 2, 1, 0, 1, 2, 0)
Panel(4, 4, 3, 1, 0, 2, 1, 0)
Panel(4, 7, 4, 1, 1, 1, 3, 30)
Panel(1, 1, 0, 2, 0, 0, 2, 0)
Panel(5, 2, 1, 2, 0, 2, 0, 0)
Panel(5, 8, 2, 2, 2, 1, 1, 0)
Panel(5, 13, 3, 2, 0, 2, 2, 45)
Panel(5, 22, 4, 2, 1, 0, 1, 0)
Panel(2, 1, 0, 3, 0, 2, 2, 0)
Panel(4, 5, 1, 3, 0, 1, 1, 0)
Panel(5, 17, 2, 3, 2, 2, 0, 0)
Panel(5, 10, 3, 3, 0, 1, 2, 0)
Panel(4, 6, 4, 3, 1, 2, 1, 0)
