// text: TrueType glyphs from the fonts povray-includes ships (found by the file resolver),
// extruded, kerned and laid out as POV-Ray lays them out: a bevelled title in timrom.ttf, a
// thin line in cyrvetic.ttf, crystal.ttf with an offset between letters, and a word cut from a
// box by CSG, on a reflective floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 2.2, -7.5>
  look_at  <0, 1.1, 0>
  right x*image_width/image_height
  angle 52
}
light_source { <-6, 10, -9> color rgb 1 }
light_source { <7, 5, -4> color rgb 0.35 }
background { color rgb <0.08, 0.1, 0.16> }

plane { y, 0
  pigment { checker color rgb <0.25, 0.27, 0.32> color rgb <0.15, 0.16, 0.2> scale 0.8 }
  finish { reflection 0.25 specular 0.2 }
}

// The title, centred by its extents (min_extent/max_extent on a text object).
#declare Title = text { ttf "timrom.ttf" "lumen" 0.35, 0 }
#declare Width = max_extent(Title).x - min_extent(Title).x;
object { Title
  pigment { color rgb <1, 0.72, 0.3> }
  finish { phong 0.9 phong_size 80 reflection 0.15 metallic }
  scale 1.9
  translate <-Width * 1.9 / 2, 0.9, 0>
}

// A line of small print with kerning pairs (AV, To, Wa).
text { ttf "cyrvetic.ttf" "AVATAR To Wave" 0.08, 0
  pigment { color rgb <0.55, 0.8, 1> }
  finish { specular 0.5 }
  scale 0.4
  translate <-1.9, 0.05, -2.6>
}

// Letters spread by an offset vector, on the left.
text { ttf "crystal.ttf" "SDL" 0.2, <0.15, 0.05, 0>
  pigment { color rgb <0.4, 1, 0.6> }
  finish { phong 0.6 }
  scale 0.7
  rotate 20 * y
  translate <-3.6, 2.4, 1.5>
}

// A word engraved into a slab.
difference {
  box { <1.2, 2.05, 1.2>, <4.2, 3.1, 1.6> }
  text { ttf "timrom.ttf" "3.7" 0.5, 0 scale 0.8 translate <1.75, 2.3, 1.0> }
  pigment { color rgb <0.85, 0.85, 0.9> }
  finish { specular 0.4 }
  rotate -15 * y
}
