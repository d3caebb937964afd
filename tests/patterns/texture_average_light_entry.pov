// An average texture_map entry lighter than adc_bailout still counts.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
plane { z, 0.37
  texture { average texture_map {
      [1 pigment { rgb 0 } finish { ambient 1 diffuse 0 }]
      [0.003 pigment { rgb 1 } finish { ambient 1 diffuse 0 }] } }
}
