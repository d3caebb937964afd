// A lit fog volume: a spotlight through a box of scattering media, with a column in the beam
// casting a shaft of shadow, a glowing sphere of emitting media with a turbulent density, and
// an absorbing glass-like block. Renders as POV-Ray 3.7 does (tests/differential).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2.2, -9> look_at <0, 1.4, 0> angle 50 }
background { rgb 0 }
light_source { <-2, 7.5, -1> rgb 3 spotlight point_at <0.5, 0, 1> radius 12 falloff 20 tightness 5 }
light_source { <5, 4, -8> rgb 0.25 shadowless }
plane { y, 0 pigment { checker rgb 0.6 rgb 0.25 scale 1.5 } finish { diffuse 0.8 ambient 0.05 } }
// The fog volume: hollow, clear, filled with scattering media.
box { <-5, 0.01, -3>, <5, 8, 6> hollow
  pigment { rgbt 1 } finish { ambient 0 diffuse 0 }
  interior { media { scattering { 1, rgb 0.06 } absorption 0.01 samples 6 intervals 4 } }
}
cylinder { <0.2, 0, 1>, <0.2, 2.6, 1>, 0.35 pigment { rgb <0.8, 0.5, 0.3> } finish { phong 0.4 } }
sphere { 0, 1 hollow
  pigment { rgbt 1 } finish { ambient 0 diffuse 0 }
  interior { media { emission rgb <1.2, 0.5, 0.15> absorption 0.4
    density { spherical turbulence 0.4 color_map { [0 rgb 0] [0.6 rgb 0.7] [1 rgb 1] } } } }
  translate <2.6, 1.3, -0.4>
}
box { <-3.4, 0, -1.2>, <-1.8, 1.6, 0.4> hollow rotate 20 * y
  pigment { rgbf <0.9, 0.95, 1, 0.9> } finish { phong 0.6 reflection 0.05 }
  interior { media { absorption rgb <0.8, 0.3, 0.1> } }
}
