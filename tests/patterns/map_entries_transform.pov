// The parent's transform written before its map still moves the map's entries; a warp
// turbulence in the parent bends them (left: pigment_map; right: list form).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
box { <-2, -1.5, 0.37>, <0, 1.5, 1>
  pigment { gradient x scale 3 pigment_map { [0 checker rgb 0 rgb 1 scale 0.2] [1 rgb <1, 0, 0>] } }
  finish { ambient 1 diffuse 0 }
}
box { <0, -1.5, 0.37>, <2, 1.5, 1>
  pigment { checker pigment { bozo scale 0.2 } pigment { rgb <0.2, 0.4, 0.9> }
            warp { turbulence 0.6 } scale 0.7 }
  finish { ambient 1 diffuse 0 }
}
