// The wave types after a noise pattern, one strip each: sine, triangle with frequency 2,
// scallop, cubic, poly 3, and a negative frequency with phase.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
#declare Plain = finish { ambient 1 diffuse 0 }
box { <-2, -1.5, 0.37>, <-1.33333, 1.5, 1>
  pigment { bozo sine_wave scale 0.4 } finish { Plain } }
box { <-1.33333, -1.5, 0.37>, <-0.666667, 1.5, 1>
  pigment { bozo triangle_wave frequency 2 scale 0.4 } finish { Plain } }
box { <-0.666667, -1.5, 0.37>, <0, 1.5, 1>
  pigment { bozo scallop_wave scale 0.4 } finish { Plain } }
box { <0, -1.5, 0.37>, <0.666667, 1.5, 1>
  pigment { bozo cubic_wave scale 0.4 } finish { Plain } }
box { <0.666667, -1.5, 0.37>, <1.33333, 1.5, 1>
  pigment { bozo poly_wave 3 scale 0.4 } finish { Plain } }
box { <1.33333, -1.5, 0.37>, <2, 1.5, 1>
  pigment { bozo frequency -2 phase 0.3 scale 0.4 } finish { Plain } }
