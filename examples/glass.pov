// Refraction: glass balls with different indices of refraction (ior), Fresnel reflection, and
// total internal reflection in a thick glass slab seen at a grazing angle.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }

camera {
  location <0, 2.5, -6>
  look_at  <0, 0.7, 0>
  right x*image_width/image_height
  angle 50
}

light_source { <-5, 8, -6> color rgb 1 }
background { color rgb <0.3, 0.4, 0.6> }

plane {
  y, 0
  pigment { checker color rgb <0.9, 0.9, 0.8> color rgb <0.2, 0.3, 0.6> scale 0.5 }
  finish { ambient 0.1 diffuse 0.8 }
}

#declare Glass = material {
  texture {
    pigment { color rgbf <1, 1, 1, 1> }
    finish { ambient 0 diffuse 0 specular 0.8 roughness 0.003 reflection { 0, 1 fresnel on } conserve_energy }
  }
  interior { ior 1.5 }
}

sphere { <-1.7, 0.75, 0>, 0.75 material { Glass } }
sphere { <0, 0.9, 0.5>, 0.9
  material { Glass interior { ior 1.1 } }
}
sphere { <1.7, 0.75, 0>, 0.75
  material { Glass interior { ior 2.4 } }
}
// A slab of glass: looking in at a grazing angle shows total internal reflection.
box { <-2.5, 0.02, -2.2>, <2.5, 0.3, -1.6>
  texture {
    pigment { color rgbf <0.8, 1, 0.9, 0.9> }
    finish { ambient 0 diffuse 0 specular 0.5 reflection 0.05 }
  }
  interior { ior 1.5 }
}
