// Light sources: a spotlight, a parallel light, a point light with distance fading, and a
// regular (non-jittered, deterministic) area light casting a soft shadow.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 5, -8>
  look_at  <0, 0.5, 0>
  right x*image_width/image_height
  angle 50
}

background { color rgb 0.05 }

plane { y, 0 pigment { color rgb 0.8 } finish { ambient 0.02 diffuse 0.9 } }

// spotlight on the left ball
light_source { <-3, 6, -2> color rgb <1, 0.8, 0.6>
  spotlight point_at <-2.2, 0, 0> radius 10 falloff 18 tightness 5
}
// a weak parallel light from the right
light_source { <8, 6, -3> color rgb <0.25, 0.3, 0.45>
  parallel point_at <0, 0, 0>
}
// a fading red point light near the right ball
light_source { <2.8, 1.5, -1.5> color rgb <1.5, 0.3, 0.3>
  fade_distance 1.5 fade_power 2
}
// a 5x5 area light above the middle ball: soft shadow without jitter
light_source { <0, 5, 0> color rgb 0.7
  area_light <2, 0, 0>, <0, 0, 2>, 5, 5
}

sphere { <-2.2, 0.7, 0>, 0.7 pigment { color rgb 0.9 } }
sphere { <0, 0.7, 0.5>, 0.7 pigment { color rgb 0.9 } }
box    { <1.7, 0, -0.4>, <2.7, 1.2, 0.6> pigment { color rgb 0.9 } }
