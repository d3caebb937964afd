// Rays along the extrusion and along the caps: an orthographic view straight down the text's
// depth (the rays run along its walls but for POV-Ray's 0.001 degree turn), a text lying with
// its back cap exactly at the eye's height, and a glass text refracting the floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <2, 0.9, -10> look_at <2, 0.9, 0> right x * 4.4 up y * 3.3 }
light_source { <-3, 6, -8> rgb 1 }
background { rgb <0.1, 0.12, 0.18> }
plane { z, 3 pigment { checker rgb 0.85 rgb 0.55 scale 0.5 } }
text { ttf "timrom.ttf" "Hello" 2, 0 pigment { rgb <1, 0.6, 0.3> } scale 0.8 translate <0, 1.6, 0> }
// The back cap (z = 0.4 before the turn) lies in the plane y = 0.9 of the eye's height.
text { ttf "cyrvetic.ttf" "flat" 0.4, 0 pigment { rgb <0.4, 0.8, 1> } rotate x * -90 translate <0.2, 0.5, 0> }
text { ttf "timrom.ttf" "B8" 0.5, 0.05
  pigment { rgbf <0.9, 1, 0.9, 0.9> } finish { reflection 0.1 } interior { ior 1.5 }
  scale 1.1 rotate <10, 30, 0> translate <2.7, -0.3, -1> }
