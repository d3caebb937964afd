// Stability: total internal reflection in a glass sphere (ior 1.5). Rays refracted into the
// sphere meet its far side beyond the critical angle (41.8 degrees) near the rim and bounce
// around inside until max_trace_level. Expected: finite pixels everywhere and the same image
// as POV-Ray.
// expect: size 64x48
// expect: povray 45
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 20 }
camera { location <0, 1, -4> look_at <0, 0, 0> }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-4, 6, -5> rgb 1 }
plane { y, -1 pigment { checker rgb 1 rgb 0.1 } }
sphere { 0, 1
  pigment { rgbf <1, 1, 1, 0.95> }
  finish { ambient 0 diffuse 0 phong 0.5 reflection { 0.02, 1 fresnel } conserve_energy }
  interior { ior 1.5 }
}
