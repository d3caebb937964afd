// Strings: UTF-8 under charset utf8 (characters timrom.ttf lacks become its missing-glyph
// box), an empty string, a one-space string, characters spaced by a negative offset so they
// overlap (the union of glyphs), and a string built with concat and str.
#version 3.7;
global_settings { assumed_gamma 1.0 charset utf8 }
camera { location <2, 1.8, -6> look_at <2, 0.6, 0> angle 42 }
light_source { <-3, 6, -5> rgb 1 }
background { rgb <0.1, 0.12, 0.18> }
plane { y, -0.35 pigment { checker rgb 0.85 rgb 0.55 scale 0.5 } }
text { ttf "timrom.ttf" "Aé€Z" 0.2, 0 pigment { rgb <1, 0.5, 0.2> } translate <0, 1.2, 0> }
text { ttf "timrom.ttf" "" 0.2, 0 pigment { rgb 1 } }
text { ttf "timrom.ttf" " " 0.2, 0 pigment { rgb 1 } }
text { ttf "cyrvetic.ttf" "OOOO" 0.3, <-0.35, 0, 0> pigment { rgb <0.4, 0.9, 0.4> } translate <0.2, 0.2, -0.5> }
text { ttf "timrom.ttf" concat("n=", str(12.5, 0, 1)) 0.3, 0 pigment { rgb <0.5, 0.6, 1> } scale 0.8 translate <2.3, -0.1, -0.3> }
