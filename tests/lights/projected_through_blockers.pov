// projected_through: the projected object placed in the scene too, a larger and a smaller
// copy, and an unseen box nearer the wall. Shadows are tested only between the lit point and
// the projected object (measured): the copy and anything nearer the light cast none.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at 0 right x * 12 up y * 6 }
plane { z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
#declare O = sphere { <0, 0, -5>, 0.6 }
union {
  object { O }                               // the same object: no shadow
  sphere { <-3, 0, -5>, 0.5 }                // smaller, behind the projected one's surface
  sphere { <3, 0, -5>, 0.8 }                 // larger: its near side shadows
  pigment { rgb <1, 0, 0> } finish { ambient 1 diffuse 0 }
}
box { <0.3, -3, -2.1>, <1, 3, -2> no_image }  // nearer the wall: a shadow
light_source { <0, 0, -10> rgb 1 projected_through { union { object { O } sphere { <-3, 0, -5>, 0.6 } sphere { <3, 0, -5>, 0.6 } } } }
light_source { <0, 0, -10> rgb 0.3 }
