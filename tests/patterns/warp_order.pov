// Warps and transforms act in the order written, including warps on a pigment whose
// pigment_map entries see the warped point (POV-Ray evaluates map entries at the parent's
// pattern point), and a transform written before the map.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
#declare F = finish { ambient 1 diffuse 0 }
#declare Inner = pigment { onion scale 0.3 translate <0.2, 0.1, 0.3>
  color_map { [0 rgb <1, 0.8, 0>] [0.5 rgb <0, 0.5, 0.2>] [1 rgb <1, 0.8, 0>] } }
box { <-2, 0, 0>, <0, 1.5, 1>
  pigment { gradient x scale 0.5 warp { repeat x * 0.4 flip x } rotate 30 * z translate 0.1
    color_map { [0 rgb 0] [0.5 rgb <1, 0.5, 0.2>] [1 rgb 0] } } finish { F } }
box { <0, 0, 0>, <2, 1.5, 1>
  pigment { gradient x rotate 30 * z warp { black_hole <1, 0.7, 0>, 0.6 } scale 0.5
    color_map { [0 rgb 0] [0.5 rgb <0.2, 0.5, 1>] [1 rgb 0] } } finish { F } }
box { <-2, -1.5, 0>, <0, 0, 1>
  pigment { gradient y warp { repeat x * 0.5 flip y } scale 0.7
    pigment_map { [0 Inner] [0.5 rgb <0.2, 0.1, 0.9>] [1 Inner] } } finish { F } }
box { <0, -1.5, 0>, <2, 0, 1>
  pigment { gradient x scale 0.6 pigment_map { [0 Inner] [0.5 Inner rotate 45 * z] [1 Inner] }
    warp { cylindrical } rotate 90 * x } finish { F } }
