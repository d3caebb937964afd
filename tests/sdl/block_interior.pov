sphere { 0, 1
  pigment { rgbf 1 }
  interior { ior 1.5 caustics 0.5 dispersion 1.02 dispersion_samples 10
             fade_distance 2 fade_power 1001 fade_color rgb <1, 0.5, 0> }
}
#declare Glass = material {
  texture { pigment { rgbt <1, 1, 1, 0.9> } finish { phong 1 } }
  interior { ior 1.33 }
}
sphere { 0, 1 material { Glass } interior_texture { pigment { rgb <1, 0, 0> } } }
