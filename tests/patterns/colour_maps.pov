// Colour-map search: an unsorted map taken literally (left), a single entry (middle) and
// close keys blended in single precision (right).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
box { <-2, -1.5, 0.37>, <-0.67, 1.5, 1>
  pigment { bozo scale 0.3 color_map { [0.8 rgb 1] [0.3 rgb 0] [0.5 rgb <1, 0, 0>] } }
  finish { ambient 1 diffuse 0 }
}
box { <-0.67, -1.5, 0.37>, <0.67, 1.5, 1>
  pigment { granite color_map { [0.4 rgb <0.2, 0.5, 0.9>] } }
  finish { ambient 1 diffuse 0 }
}
box { <0.67, -1.5, 0.37>, <2, 1.5, 1>
  pigment { bozo scale 0.3 color_map { [0.3 rgb <0.1, 0.3, 0.7>] [0.3001 rgb <0.9, 0.6, 0.2>]
                                       [0.7 rgb <0.3, 0.9, 0.4>] } }
  finish { ambient 1 diffuse 0 }
}
