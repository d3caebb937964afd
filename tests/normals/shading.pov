// The perturbed normal in the rest of shading: phong and specular highlights, reflection and
// refraction directions, layered textures (each layer its own normal) and a texture_map
// (each entry its own normal).
#include "common.inc"
plane { z, 3 pigment { checker rgb <1, 0.2, 0.1> rgb <0.1, 0.3, 1> scale 0.5 } finish { ambient 1 diffuse 0 } }
sphere { 0, 0.66
  texture { Matte normal { gradient x 3 sine_wave scale 0.25 } finish { phong 1 phong_size 30 } }
  translate Cell(0, 0) }
sphere { 0, 0.66
  texture { Matte normal { gradient y 3 sine_wave scale 0.25 } finish { specular 0.8 roughness 0.02 } }
  translate Cell(1, 0) }
sphere { 0, 0.66
  texture { Matte normal { onion 2 sine_wave scale 0.2 translate <0.4, 0.4, -1> }
            finish { diffuse 0.3 reflection 0.7 } }
  translate Cell(2, 0) }
sphere { 0, 0.66
  texture { pigment { rgbf <1, 1, 1, 0.9> } finish { ambient 0 diffuse 0.1 phong 0.5 }
            normal { gradient x 2 sine_wave scale 0.3 } }
  interior { ior 1.5 }
  translate Cell(0, 1) }
sphere { 0, 0.66
  texture { Matte normal { gradient x 3 sine_wave scale 0.2 } }
  texture { pigment { rgbt <1, 0.6, 0.3, 0.5> } finish { ambient 0 diffuse 0.7 phong 0.8 }
            normal { gradient y 3 sine_wave scale 0.3 } }
  translate Cell(1, 1) }
sphere { 0, 0.66
  texture { gradient x
    texture_map { [0.3 Matte normal { gradient y 3 sine_wave scale 0.15 }]
                  [0.7 pigment { rgb <1, 0.8, 0.5> } finish { ambient 0 diffuse 1 reflection 0.5 }
                       normal { onion 2 sine_wave scale 0.15 }] }
    scale 0.8 translate -0.4*x }
  translate Cell(2, 1) }
