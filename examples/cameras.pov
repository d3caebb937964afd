// POV-Ray's camera types on one scene: a ring of coloured columns around the eye, a checker
// floor and a sky. Declare Cam (default 0) to choose: 0 perspective, 1 orthographic,
// 2 fisheye, 3 ultra_wide_angle, 4 omnimax, 5 panoramic, 6-9 cylinder 1-4, 10 spherical,
// 11 perspective with focal blur, 12 perspective with a camera normal (wavy glass).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (Cam) #declare Cam = 0; #end

camera {
  #switch (Cam)
    #case (1) orthographic #break
    #case (2) fisheye angle 180 #break
    #case (3) ultra_wide_angle angle 170 #break
    #case (4) omnimax angle 200 #break
    #case (5) panoramic #break
    #case (6) cylinder 1 angle 200 #break
    #case (7) cylinder 2 angle 120 #break
    #case (8) cylinder 3 angle 200 #break
    #case (9) cylinder 4 angle 120 #break
    #case (10) spherical angle 300, 150 #break
    #else perspective angle 70
  #end
  location <0, 1.6, -1.5>
  #if (Cam = 1)
    right 8 * x * image_width / image_height up 8 * y
  #else
    right x * image_width / image_height
  #end
  look_at <0, 1.2, 3>
  #if (Cam = 11)
    aperture 0.3 blur_samples 7 focal_point <0, 1, 4>
  #end
  #if (Cam = 12)
    normal { ripples 0.25 frequency 6 }
  #end
}
light_source { <4, 10, -6> color rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.9, 0.85, 0.8>] [0.4 rgb <0.35, 0.5, 0.85>] } } }
plane { y, 0 pigment { checker color rgb 0.85 color rgb 0.3 } finish { diffuse 0.8 } }

// Twelve columns on a circle of radius 5 around the origin, each topped by a ball.
#for (I, 0, 11)
  #local A = I * 30;
  #local C = <0.5 + 0.5 * sin(radians(A)), 0.5 + 0.5 * sin(radians(A + 120)),
              0.5 + 0.5 * sin(radians(A + 240))>;
  union {
    cylinder { 0, 2.2 * y, 0.35 }
    sphere { 2.6 * y, 0.45 }
    pigment { color rgb C }
    finish { phong 0.6 }
    translate <5 * sin(radians(A)), 0, 5 * cos(radians(A))>
  }
#end
