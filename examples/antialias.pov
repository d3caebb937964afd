// Anti-aliasing: a high-contrast checkerboard receding to the horizon plus thin tilted bars;
// compare renders with -A and with +A0.3 +AM1 +R3 to see the jagged edges smoothed.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 1.5, -5>
  look_at  <0, 0.8, 0>
  right x*image_width/image_height
  angle 55
}

light_source { <-4, 10, -8> color rgb 1 }
background { color rgb <0.4, 0.6, 0.9> }

plane {
  y, 0
  pigment { checker color rgb 1 color rgb 0 }
  finish { ambient 0.2 diffuse 0.8 }
}

#declare I = 0;
#while (I < 7)
  box { <-0.03, 0, -0.03>, <0.03, 2.5, 0.03>
    rotate z*(I*6 - 18)
    translate <I*0.5 - 1.5, 0, 1>
    pigment { color rgb <1, 0.2, 0.1> }
    finish { ambient 0.2 diffuse 0.8 }
  }
  #declare I = I + 1;
#end
