// Participating media against POV-Ray (16-bit linear output where compared closely). Declare
// Kind:
//  0 constant emission in a hollow clear sphere      1 absorption and emission, intervals 3
//  2 a spherical density with a density_map           3 isotropic scattering, a point light
//  4 a spotlit atmosphere (lit and unlit intervals)   5 method 2, samples 4
//  6 Henyey-Greenstein scattering, eccentricity 0.6   7 two media in one interior, nested containers
//  8 the camera inside a hollow container             9 a non-hollow container: no media
#ifndef (Kind) #declare Kind = 0; #end
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.5, -6> look_at 0 angle 40 }
background { rgb <0.1, 0.12, 0.2> }
plane { y, -1.2 pigment { checker rgb 0.8 rgb 0.3 } finish { ambient 0.2 diffuse 0.6 } }
#declare Clear = material { texture { pigment { rgbt 1 } finish { ambient 0 diffuse 0 } } }
#switch (Kind)
#case (0)
  sphere { 0, 1.2 material { Clear interior { media { emission rgb <0.5, 0.3, 0.1> } } } hollow }
  #break
#case (1)
  box { -1, 1 material { Clear interior { media { absorption rgb <0.2, 0.6, 1> emission 0.15 intervals 3 } } } hollow rotate 30 * y }
  #break
#case (2)
  sphere { 0, 1.3 material { Clear interior { media { emission 1 absorption 0.5
      density { spherical density_map { [0 rgb 0] [0.5 rgb <0.2, 0.6, 0.3>] [1 rgb 1] } scale 1.3 } } } } hollow }
  #break
#case (3)
  light_source { <3, 4, -2> rgb 1 }
  sphere { 0, 1.2 material { Clear interior { media { scattering { 1, rgb 0.6 } samples 6 } } } hollow }
  #break
#case (4)
  light_source { <0, 4, 0> rgb 2 spotlight point_at <0, -1, 0> radius 10 falloff 18 }
  media { scattering { 1, 0.05 } absorption 0.01 samples 6 intervals 4 }
  box { <-3, -1.3, -3>, <3, 4.5, 3> hollow pigment { rgbt 1 } }  // the media stops here
  sphere { <-4, 4, 8>, 0.1 pigment { rgb 1 } }
  #break
#case (5)
  sphere { 0, 1.2 material { Clear interior { media { method 2 samples 4 emission rgb <0.2, 0.5, 0.9>
      density { bozo color_map { [0 rgb 0] [1 rgb 1] } scale 0.5 } } } } hollow }
  #break
#case (6)
  light_source { <0, 1, 6> rgb 1.5 }
  sphere { 0, 1.2 material { Clear interior { media { scattering { 5, rgb 0.5 eccentricity 0.6 } } } } hollow }
  #break
#case (7)
  sphere { 0, 1.3 material { Clear interior { media { emission rgb <0.3, 0, 0> } media { emission rgb <0, 0, 0.3> absorption 0.4 } } } hollow }
  sphere { <0.3, 0.2, -0.5>, 0.6 material { Clear interior { media { emission rgb <0, 0.8, 0> intervals 2 } } } hollow }
  #break
#case (8)
  sphere { 0, 20 material { Clear interior { media { absorption 0.05 emission rgb <0.01, 0.02, 0.03> } } } hollow }
  #break
#case (9)
  sphere { 0, 1.2 material { Clear interior { media { emission rgb <0.5, 0.3, 0.1> } } } }
  #break
#end
