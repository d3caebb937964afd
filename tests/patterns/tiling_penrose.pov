// Tilings 25, 26 and 27 (Penrose pentagons, kites and darts, rhombs) viewed from above the x-z
// plane: smooth maps over the bevels and maps with a hard key at every k/T (which side of it
// each tile's flat falls), at several scales and turns, near the origin (where the tilings'
// five-fold centre sits) and moved out to x, z ~ 1000 and ~ 1e5; all nudged off the tilings'
// symmetry lines, where renderers may break ties between tiles apart.
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
#macro Panel(N, Col, Row, Map, S, R, T)
  box { <-2.5 + Col, 1 - Row, 0>, <-1.5 + Col, 2 - Row, 1>
    pigment { tiling N color_map { Map } scale S translate <0.0123, 0, 0.0371> rotate R * y translate T transform { Up } }
    finish { F } }
#end
#declare Far = <1000.3, 0, -77.7>;
#declare Farther = <123456.7, 0, -98765.4>;
Panel(25, 0, 0, Ramp, 0.15, 0, <2.5, 0, -1.5>)  // the centre of each tiling in its panel's middle
Panel(26, 1, 0, Ramp, 0.3, 0, <1.5, 0, -1.5>)
Panel(27, 2, 0, Ramp, 0.3, 0, <0.5, 0, -1.5>)
Panel(25, 3, 0, Keys(6), 0.12, 10, 0)
Panel(26, 4, 0, Keys(2), 0.2, 10, 0)
Panel(27, 0, 1, Keys(2), 0.2, -20, 0)
Panel(25, 1, 1, Ramp, 0.3, 0, 0)
Panel(26, 2, 1, Ramp, 0.1, 30, 0)
Panel(27, 3, 1, Ramp, 0.1, 0, 0)
Panel(25, 4, 1, Ramp, 0.06, 45, 0)
Panel(25, 0, 2, Ramp, 0.12, 0, Far)
Panel(26, 1, 2, Ramp, 0.25, 0, Far)
Panel(27, 2, 2, Ramp, 0.25, 0, Far)
Panel(25, 3, 2, Keys(6), 0.1, 15, Far)
Panel(26, 4, 2, Keys(2), 0.15, 0, Far)
Panel(27, 0, 3, Keys(2), 0.12, -10, Far)
Panel(25, 1, 3, Ramp, 0.12, 0, Farther)
Panel(26, 2, 3, Ramp, 0.25, 0, Farther)
Panel(27, 3, 3, Ramp, 0.25, 0, Farther)
Panel(25, 4, 3, Keys(6), 0.15, 0, Farther)
