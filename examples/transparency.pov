// Transparency: filter (coloured glass that tints light passing through it) versus transmit
// (light passes unchanged), with the coloured shadows they cast on a white floor.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }

camera {
  location <0, 4, -6.5>
  look_at  <0, 0.5, 0>
  right x*image_width/image_height
  angle 50
}

light_source { <2, 8, -3> color rgb 1 }
background { color rgb 0.2 }

plane { y, 0 pigment { color rgb 1 } finish { ambient 0.1 diffuse 0.8 } }

// filtered panes: red, green and blue stained glass, no refraction
#declare I = 0;
#while (I < 3)
  box { <-0.5, 0.01, -0.05>, <0.5, 1.5, 0.05>
    pigment { color rgbf <(I = 0), (I = 1), (I = 2), 0.9> }
    finish { ambient 0.05 diffuse 0.1 }
    translate <-1.6 + I*1.6, 0, 0.8>
  }
  #declare I = I + 1;
#end

// transmitting balls: half-transparent without tint, and a filter+transmit mix
sphere { <-1, 0.6, -0.8>, 0.6
  pigment { color rgbt <1, 0.8, 0.2, 0.5> }
  finish { ambient 0.1 diffuse 0.6 specular 0.4 }
}
sphere { <1, 0.6, -0.8>, 0.6
  pigment { color rgbft <0.2, 0.4, 1, 0.5, 0.3> }
  finish { ambient 0.1 diffuse 0.6 specular 0.4 }
}
