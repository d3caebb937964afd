// The scene's settings in the noise normals: number_of_waves for ripples and waves,
// noise_generator for the magnitude of dents (the pattern's own noise_generator first).
#version 3.7;
global_settings { assumed_gamma 1 number_of_waves 3 noise_generator 1 }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
light_source { <1000, 1000, -2000> rgb 1 parallel point_at 0 }
#declare Matte = texture { pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
#macro Ball(I, J, N)
  sphere { 0, 0.66 texture { Matte normal { N } } translate <-1.35 + 1.35*I, 0.72 - 1.45*J, 0> }
#end
Ball(0, 0, normal { ripples 3 scale 0.1 })
Ball(1, 0, normal { waves 3 frequency 2 scale 0.1 })
Ball(2, 0, normal { dents 4 scale 0.2 })
Ball(0, 1, normal { dents 4 scale 0.2 noise_generator 2 })
Ball(1, 1, normal { granite 0.5 scale 0.5 })
Ball(2, 1, normal { bozo 2 scale 0.15 })
