light_source { <0, 5, 0>, 1
  area_light x, z, 0, 4
}
