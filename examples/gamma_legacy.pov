// Gamma handling, legacy style: #version 3.6 and no assumed_gamma, so colours are written to
// the image as given (no linear-light gamma encoding) and the grey ramp looks darker than the
// same ramp in gamma.pov, which uses #version 3.7 and assumed_gamma 1.0.
#version 3.6;

camera {
  location <0, 0, -5>
  look_at  <0, 0, 0>
  right x*image_width/image_height
  angle 50
}

light_source { <0, 0, -10> color rgb 1 }
background { color rgb <0.5, 0.5, 0.5> }

// a ramp of grey boxes (0.1 .. 1.0) above a smooth gradient
#declare I = 0;
#while (I < 10)
  box { <-0.2, -0.2, -0.2>, <0.2, 0.2, 0.2>
    translate <(I - 4.5) * 0.45, 0.8, 0>
    pigment { color rgb (I + 1) / 10 }
    finish { ambient 1 diffuse 0 }
  }
  #declare I = I + 1;
#end

box { <-2.25, -1.2, -0.2>, <2.25, 0.2, 0.2>
  pigment { gradient x color_map { [0 color rgb 0] [1 color rgb 1] } scale 4.5 translate -2.25*x }
  finish { ambient 1 diffuse 0 }
}
