// Tilings 4, 6, 7, 8, 11-15 and 18 (square and rectangle families) viewed from above the x-z
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
Panel(4, 0, 0, Ramp, 0.2, 0)
Panel(6, 1, 0, Ramp, 0.12, 0)
Panel(7, 2, 0, Ramp, 0.15, 10)
Panel(8, 3, 0, Ramp, 0.15, 0)
Panel(11, 4, 0, Ramp, 0.1, 0)
Panel(12, 0, 1, Ramp, 0.08, 0)
Panel(13, 1, 1, Ramp, 0.15, -20)
Panel(14, 2, 1, Ramp, 0.15, 0)
Panel(15, 3, 1, Ramp, 0.1, 0)
Panel(18, 4, 1, Ramp, 0.12, 30)
Panel(4, 0, 2, Keys(1), 0.2, 15)
Panel(6, 1, 2, Keys(2), 0.12, 0)
Panel(7, 2, 2, Keys(2), 0.15, 0)
Panel(8, 3, 2, Keys(3), 0.15, 0)
Panel(11, 4, 2, Keys(3), 0.1, 0)
Panel(12, 0, 3, Keys(3), 0.08, 0)
Panel(13, 1, 3, Keys(3), 0.15, 0)
Panel(14, 2, 3, Keys(5), 0.15, 0)
Panel(15, 3, 3, Keys(2), 0.1, 0)
Panel(18, 4, 3, Keys(2), 0.12, 0)
