// Lights with shapes: a projected_through light shines only through a ring-shaped window, a
// lamp built as a union carries its own light source (lights inside CSG move with the
// object), and an open bowl shows its interior_texture on the inside faces.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 5, -8>
  look_at  <0, 0.5, 0>
  right x*image_width/image_height
  angle 50
}

background { color rgb 0.05 }
plane { y, 0 pigment { color rgb 0.8 } finish { ambient 0.05 diffuse 0.9 } }

// The window: light from above passes only through the torus-shaped opening.
light_source { <0, 10, 0> color rgb 1
  projected_through { torus { 1.2, 0.35 translate <1, 5, 0> } }
}

// A lamp: a glowing ball with its own light, placed as one object.
#declare Lamp = union {
  sphere { 0, 0.2 pigment { color rgb <1, 0.9, 0.6> } finish { ambient 1 diffuse 0 } no_shadow }
  light_source { 0 color rgb <0.6, 0.5, 0.3> }
}
object { Lamp translate <-2.5, 1.5, -1> }

// The bowl: red outside, green inside.
sphere { 0, 1
  clipped_by { plane { y, 0.3 } }
  texture { pigment { color rgb <0.9, 0.2, 0.1> } finish { phong 0.5 } }
  interior_texture { pigment { color rgb <0.2, 0.8, 0.3> } }
  translate <-1, 1, 1>
}
