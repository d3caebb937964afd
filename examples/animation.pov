// A ball rolling across the floor, driven by `clock` (0 to 1).
//   lumen examples/animation.pov +KFI1 +KFF24 +W320 +H240   -> animation01.png .. animation24.png
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2, -6> look_at <0, 0.6, 0> }
light_source { <-4, 6, -5> color rgb 1 }
background { color rgb <0.6, 0.75, 0.9> }

plane { y, 0 pigment { checker color rgb 0.85 color rgb 0.45 } }

#declare X = -2.5 + 5 * clock;
sphere {
  0, 0.6
  pigment { gradient x color_map { [0.5 color rgb <0.9, 0.2, 0.1>] [0.5 color rgb 0.95] } scale 0.6 }
  finish { phong 0.7 phong_size 40 }
  rotate z * -degrees(5 * clock / 0.6)
  translate <X, 0.6, 0>
}
