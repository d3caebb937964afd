// CSG operations side by side: union vs merge of transparent spheres (merge hides the inner
// surfaces), intersection, difference, and a sphere clipped_by a plane.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }

camera {
  location <0, 4, -9>
  look_at  <0, 0.8, 0>
  right x*image_width/image_height
  angle 50
}

light_source { <-5, 9, -8> color rgb 1 }
background { color rgb <0.2, 0.25, 0.35> }

plane { y, 0 pigment { checker color rgb 0.85 color rgb 0.35 } finish { ambient 0.1 diffuse 0.8 } }

#declare Clear = texture {
  pigment { color rgbt <0.4, 0.8, 1, 0.6> }
  finish { ambient 0.1 diffuse 0.5 specular 0.6 }
}

// union: the inner surfaces of the overlapping spheres show through
union {
  sphere { <-0.35, 0, 0>, 0.6 }
  sphere { < 0.35, 0, 0>, 0.6 }
  texture { Clear }
  translate <-3.3, 0.7, 0>
}
// merge: the same spheres without the inner surfaces
merge {
  sphere { <-0.35, 0, 0>, 0.6 }
  sphere { < 0.35, 0, 0>, 0.6 }
  texture { Clear }
  translate <-1.1, 0.7, 0>
}
// intersection: a box with its corners rounded off by a sphere
intersection {
  box { <-0.7, -0.7, -0.7>, <0.7, 0.7, 0.7> }
  sphere { 0, 0.9 }
  pigment { color rgb <1, 0.6, 0.1> }
  finish { ambient 0.1 diffuse 0.7 specular 0.4 }
  rotate y*30
  translate <1.1, 0.7, 0>
}
// difference: a box with a spherical bite and a hole
difference {
  box { <-0.6, -0.6, -0.6>, <0.6, 0.6, 0.6> }
  sphere { <0.6, 0.6, -0.6>, 0.6 }
  cylinder { <0, 0, -1>, <0, 0, 1>, 0.25 }
  pigment { color rgb <0.3, 0.9, 0.4> }
  finish { ambient 0.1 diffuse 0.7 specular 0.4 }
  rotate y*-20
  translate <3.3, 0.6, 0>
}
// clipped_by: an open hemisphere shell in front
sphere { 0, 0.7
  clipped_by { plane { y, 0.2 } }
  pigment { color rgb <0.9, 0.2, 0.3> }
  finish { ambient 0.2 diffuse 0.7 }
  translate <0, 0.5, -2.3>
}
