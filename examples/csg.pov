// Constructive solid geometry on a checkered floor: difference, intersection, union, a mirror
// finish and a spotlight. Rendered without anti-aliasing in the differential suite.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }

camera {
  location <0, 3, -7>
  look_at  <0, 0.9, 0>
  angle 45
}

light_source { <-5, 8, -6> color rgb 0.9 }
light_source {
  <4, 7, -2> color rgb <1, 0.9, 0.7>
  spotlight point_at <1.6, 0, 0.5> radius 12 falloff 20 tightness 10
}

background { color rgb <0.1, 0.12, 0.2> }

plane {
  y, 0
  pigment { checker color rgb 0.9 color rgb 0.25 scale 0.8 }
  finish { ambient 0.05 diffuse 0.8 reflection 0.15 }
}

#declare Carved = difference {
  box { <-0.9, 0, -0.9>, <0.9, 1.8, 0.9> }
  sphere { <0, 1.8, 0>, 1.1 }
  cylinder { <-1, 0.6, 0>, <1, 0.6, 0>, 0.35 }
}

object {
  Carved
  rotate y * 25
  translate <-1.7, 0, 0.6>
  pigment { color rgb <0.9, 0.55, 0.15> }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 30 }
}

// A lens: the intersection of two spheres
intersection {
  sphere { <0, 0, -0.6>, 1 }
  sphere { <0, 0, 0.6>, 1 }
  rotate x * -20
  translate <0, 0.9, -0.4>
  pigment { color rgb <0.3, 0.8, 0.4> }
  finish { ambient 0.1 diffuse 0.6 phong 0.9 phong_size 80 }
}

// A mirror ball on a cone stand
union {
  cone { <0, 0, 0>, 0.5, <0, 0.8, 0>, 0.15 }
  sphere { <0, 1.4, 0>, 0.6 }
  translate <1.8, 0, 0.8>
  pigment { color rgb 0.8 }
  finish { ambient 0.05 diffuse 0.3 reflection 0.6 metallic phong 0.6 phong_size 100 }
}
