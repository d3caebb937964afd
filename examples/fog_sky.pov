// Atmosphere: a sky_sphere with a gradient colour map above a checkered ground plane that
// fades into constant fog with distance.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 1.5, -6>
  look_at  <0, 1.2, 0>
  right x*image_width/image_height
  angle 60
}

light_source { <-10, 20, -15> color rgb 1 }

sky_sphere {
  pigment {
    gradient y
    color_map { [0 color rgb <0.9, 0.8, 0.7>] [0.3 color rgb <0.4, 0.6, 1>] [1 color rgb <0.05, 0.15, 0.5>] }
  }
}

fog { distance 25 color rgbt <0.8, 0.8, 0.85, 0.1> }

plane { y, 0
  pigment { checker color rgb <0.2, 0.6, 0.2> color rgb <0.8, 0.8, 0.6> scale 2 }
  finish { ambient 0.15 diffuse 0.8 }
}

#declare I = 0;
#while (I < 6)
  sphere { <-3 + I*1.5, 1, I*6>, 1
    pigment { color rgb <1, 0.3, 0.2> }
    finish { ambient 0.1 diffuse 0.8 specular 0.5 }
  }
  #declare I = I + 1;
#end
