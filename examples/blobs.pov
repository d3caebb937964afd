// Blobs: a molecule of sphere components with their own textures (blended where they meet), a
// chain of cylinder components, and a negative component carving a dimple, plus a ring of
// ovus eggs; all under one light with reflections on the floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 3.5, -7.5>
  look_at  <0, 0.9, 0>
  right x*image_width/image_height
  angle 48
}
light_source { <-5, 10, -7> color rgb 1 }
light_source { <6, 5, -5> color rgb 0.3 }
background { color rgb <0.12, 0.13, 0.18> }

plane { y, 0
  pigment { color rgb <0.35, 0.37, 0.42> }
  finish { reflection 0.2 specular 0.2 }
}

#declare Glossy = finish { phong 0.7 phong_size 60 }
// A molecule: each atom's texture is blended by its share of the field.
blob { threshold 0.6
  sphere { <0, 0, 0>, 1.0, 1 texture { pigment { color rgb <0.9, 0.2, 0.15> } finish { Glossy } } }
  sphere { <0.85, 0.5, 0>, 0.7, 1 texture { pigment { color rgb 0.95 } finish { Glossy } } }
  sphere { <-0.85, 0.5, 0>, 0.7, 1 texture { pigment { color rgb 0.95 } finish { Glossy } } }
  sphere { <0, -0.2, -0.9>, 0.6, 1 texture { pigment { color rgb <0.2, 0.4, 0.95> } finish { Glossy } } }
  translate <-2.4, 1.2, 0.5>
}

// A chain of cylinders, bent, with a negative sphere pressing a dimple into it.
blob { threshold 0.5
  cylinder { <-0.8, 0, 0>, <0, 0.9, 0>, 0.45, 1 }
  cylinder { <0, 0.9, 0>, <0.8, 0, 0>, 0.45, 1 }
  cylinder { <0.8, 0, 0>, <0.8, 0, -1>, 0.45, 1 }
  sphere { <0, 1.25, -0.1>, 0.5, -1.5 }
  pigment { color rgb <0.3, 0.85, 0.45> }
  finish { phong 0.8 reflection 0.1 }
  translate <0.6, 0.45, 0.8>
}

// A ring of eggs.
#for (I, 0, 5)
  ovus { 0.22, 0.14
    pigment { color rgb <1, 0.85 - I * 0.08, 0.4 + I * 0.08> }
    finish { Glossy }
    translate <0.65 * sin(radians(I * 60)), 0, 0.65 * cos(radians(I * 60))>
    translate <2.3, 0, -0.9>
  }
#end
