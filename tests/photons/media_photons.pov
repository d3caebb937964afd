// Media photons (global photons { media N, factor }): a glass sphere focuses a spotlight's
// photons into a box of scattering media, whose beam is lit by the photons alone (the clear
// box is a refracting target, so with surface photons it shadows the direct light).
#version 3.7;
global_settings {
    assumed_gamma 1
    photons { count 20000 media 60, 1 }
}
camera { location <0, 1.2, -6> look_at <0, 0.8, 0> angle 45 }
light_source { <0, 8, 0> rgb 1
    spotlight radius 8 falloff 10 point_at <0, 0, 0>
    photons { refraction on reflection on }
}
light_source { <-3, 4, -6> rgb 0.3 photons { refraction off reflection off } media_interaction off }
plane { y, 0 pigment { checker rgb 0.7 rgb 0.4 } }
box { <-1.5, 0, -1.5>, <1.5, 2.5, 1.5> hollow
    pigment { rgbf 1 }
    interior { media { scattering { 1, rgb 0.3 extinction 0 } method 3 intervals 1 samples 4 } }
    photons { target }
}
sphere { <0, 3.4, 0>, 0.6
    pigment { rgbf <0.9, 0.95, 1, 1> }
    finish { ambient 0 diffuse 0 }
    interior { ior 1.5 }
    photons { target refraction on reflection off collect off }
}
