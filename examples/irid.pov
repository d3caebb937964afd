// Iridescence (finish irid): thin-film interference tints the light each surface receives,
// with colours that change with the angles to the light and the eye. Soap-bubble spheres
// with different film thicknesses, and an oily floor; irid_wavelength sets the film's
// red/green/blue wavelengths.
#version 3.7;
global_settings { assumed_gamma 1.0 irid_wavelength <0.65, 0.52, 0.45> }

camera {
  location <0, 3, -7>
  look_at  <0, 0.8, 0>
  right x*image_width/image_height
  angle 50
}

background { color rgb <0.05, 0.05, 0.1> }
light_source { <-5, 8, -6> color rgb 1 }
light_source { <6, 4, -4> color rgb 0.4 }

plane { y, 0
  pigment { color rgb 0.3 }
  finish { ambient 0.05 diffuse 0.8 irid { 0.6 thickness 0.9 } }
}

#declare Film = finish { ambient 0.05 diffuse 0.6 phong 0.8 phong_size 60 };
sphere { <-2.2, 1, 0>, 1
  pigment { color rgb 0.9 }
  finish { Film irid { 0.35 thickness 0.25 } }
}
sphere { <0, 1, 0.5>, 1
  pigment { color rgb 0.9 }
  finish { Film irid { 0.5 thickness 0.5 } }
}
sphere { <2.2, 1, 0>, 1
  pigment { color rgb <0.9, 0.8, 0.6> }
  finish { Film irid { 0.7 thickness 1.2 } }
}
