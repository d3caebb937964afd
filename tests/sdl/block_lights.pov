light_source { <10, 10, -10>, rgb <1, 0.9, 0.8> }
light_source { <0, 5, 0> color rgb 2 spotlight point_at <0, 0, 1> radius 15 falloff 35
  tightness 5 fade_distance 3 fade_power 2 }
light_source { 0, 1 cylinder point_at -y translate y*4 }
light_source { <0, 100, 0>, 1 parallel point_at 0 shadowless }
