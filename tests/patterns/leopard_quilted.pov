// leopard; quilted with the default controls and with control0/control1, and quilted with
// a frequency (which brings back the frequency/phase step POV-Ray skips for quilted).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
#declare F = finish { ambient 1 diffuse 0 }
#declare Ramp = color_map { [0 rgb <0.1, 0, 0.3>] [0.3 rgb <1, 0.3, 0>] [0.6 rgb <1, 1, 0.4>] [1 rgb <0.2, 0.6, 1>] }
box { <-2, 0, 0>, <0, 1.5, 1> pigment { leopard color_map { Ramp } scale 0.08 rotate <10, 20, 0> } finish { F } }
box { <0, 0, 0>, <2, 1.5, 1> pigment { quilted color_map { Ramp } scale 0.4 rotate <30, 20, 0> } finish { F } }
box { <-2, -1.5, 0>, <0, 0, 1>
  pigment { quilted control0 0.2 control1 1.5 color_map { Ramp } scale 0.5 rotate <20, 40, 0> } finish { F } }
box { <0, -1.5, 0>, <2, 0, 1>
  pigment { quilted control0 -0.5 control1 0.7 frequency 2 phase 0.1 sine_wave color_map { Ramp } scale 0.6 rotate <40, 10, 0> } finish { F } }
