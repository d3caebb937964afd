// irid turbulence uses the scene's noise generator; a sphere, so the view and light angles vary.
#version 3.7;
global_settings { assumed_gamma 1 noise_generator 1 }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
light_source { <-500, 800, -1000> rgb 1 }
sphere { 0, 1.4
  pigment { rgb <0.7, 0.6, 0.5> }
  finish { ambient 0.1 diffuse 0.7 irid { 0.4 thickness 0.3 turbulence 0.8 } }
  scale 1.2
}
