light_source { <0, 5, 0>, 1
  area_light x*2, z*2, 3, 5 adaptive 1 jitter circular orient
  area_illumination on
  looks_like { sphere { 0, 0.2 pigment { rgb 1 } } }
  rotate z*90
}
