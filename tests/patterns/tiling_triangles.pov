// Tilings 9, 16, 17 and 19-24 (triangle, hexagon and dodecagon families) viewed from above the x-z
// plane: smooth maps over the bevels, and maps with hard keys at every k/T (they show on which
// side of a key each tile's flat falls), some panels scaled, rotated and moved far out; all
// nudged off the tilings' symmetry lines, where the renderers may break ties between tiles apart.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> direction z right 5*x up 4*y }
#declare F = finish { ambient 1 diffuse 0 }
#declare Ramp = color_map { [0 rgb <0.1, 0, 0.3>] [0.3 rgb <1, 0.3, 0>] [0.6 rgb <1, 1, 0.4>] [1 rgb <0.2, 0.6, 1>] }
#declare Up = transform { rotate -90 * x }  // the tilings' x-z plane faces the camera
#macro Keys(T)  // a step at every k/T, each flat a different colour
  color_map {
    #local K = 0;
    #while (K < T)
      [K / T rgb <mod(K, 2), K / T, 1 - K / T>] [(K + 1) / T rgb <mod(K, 2), K / T, 1 - K / T> * 0.6]
      #local K = K + 1;
    #end
  }
#end
#macro Panel(N, Col, Row, Map, S, R)
  box { <-2.5 + Col, 1 - Row, 0>, <-1.5 + Col, 2 - Row, 1>
    pigment { tiling N color_map { Map } scale S translate <0.0123, 0, 0.0371> rotate R * y translate <1000.3, 0, -77.7> * (Row = 3) transform { Up } }
    finish { F } }
#end
Panel(9, 0, 0, Ramp, 0.15, 0)
Panel(16, 1, 0, Ramp, 0.1, 0)
Panel(17, 2, 0, Ramp, 0.1, 25)
Panel(19, 3, 0, Ramp, 0.1, 0)
Panel(20, 4, 0, Ramp, 0.1, 0)
Panel(21, 0, 1, Ramp, 0.12, 0)
Panel(22, 1, 1, Ramp, 0.08, -10)
Panel(23, 2, 1, Ramp, 0.07, 0)
Panel(24, 3, 1, Ramp, 0.07, 0)
Panel(9, 0, 2, Keys(3), 0.15, 15)
Panel(16, 1, 2, Keys(3), 0.1, 0)
Panel(17, 2, 2, Keys(6), 0.1, 0)
Panel(19, 3, 2, Keys(3), 0.1, 0)
Panel(20, 4, 2, Keys(3), 0.1, 0)
Panel(21, 0, 3, Keys(6), 0.12, 0)
Panel(22, 1, 3, Keys(3), 0.08, 0)
Panel(23, 2, 3, Keys(3), 0.07, 0)
Panel(24, 3, 3, Keys(5), 0.07, 0)
