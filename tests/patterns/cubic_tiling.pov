// The cubic pattern (default colours, and a list of colours), and tilings 1, 2, 3, 5 and 10,
// viewed from above the x-z plane with smooth colour maps over each tile's bevel.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
#declare F = finish { ambient 1 diffuse 0 }
#declare Ramp = color_map { [0 rgb <0.1, 0, 0.3>] [0.3 rgb <1, 0.3, 0>] [0.6 rgb <1, 1, 0.4>] [1 rgb <0.2, 0.6, 1>] }
#declare Up = transform { rotate -90 * x }  // the tilings' x-z plane faces the camera
box { <-2, 0, 0>, <-1, 1.5, 1> pigment { cubic rotate <30, 40, 0> translate <-1.5, 0.75, 0.5> } finish { F } }
box { <-1, 0, 0>, <0, 1.5, 1>
  pigment { cubic rgb 1, rgb 0.8, rgb <0.3, 0.9, 0.2>, rgb <0, 0, 0.5>, rgb 0.2, rgb <1, 0.5, 0>
    rotate <30, 40, 0> translate <-0.5, 0.75, 0.5> } finish { F } }
box { <0, 0, 0>, <1, 1.5, 1> pigment { tiling 1 color_map { Ramp } scale 0.3 transform { Up } } finish { F } }
box { <1, 0, 0>, <2, 1.5, 1> pigment { tiling 5 color_map { Ramp } scale 0.3 transform { Up } } finish { F } }
box { <-2, -1.5, 0>, <-1, 0, 1> pigment { tiling 2 color_map { Ramp } scale 0.3 transform { Up } } finish { F } }
box { <-1, -1.5, 0>, <0, 0, 1> pigment { tiling 3 color_map { Ramp } scale 0.35 transform { Up } } finish { F } }
box { <0, -1.5, 0>, <1, 0, 1> pigment { tiling 10 color_map { Ramp } scale 0.3 rotate 20 * y transform { Up } } finish { F } }
box { <1, -1.5, 0>, <2, 0, 1> pigment { tiling 5 color_map { Ramp } scale 0.4 rotate -35 * y translate 0.2 transform { Up } } finish { F } }
