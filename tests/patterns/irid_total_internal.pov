// irid tints a total internal reflection inside a glass cylinder (the bright bands of diffract.pov).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }
camera { location <3.5, -15, 3> direction <0,0,1.6542> sky z up z right x*4/3 look_at <0,0,-2.75> angle 45 }
light_source { <0, 95, 65> rgb <1,1,0>*20 fade_distance 20 fade_power 2 }
plane { z, -2 pigment { rgb 0.6 } }
cylinder { <-3,0,0>, <3,0,0>, 0.3
  pigment { rgbf 1 } finish { diffuse 0.000001 metallic on ambient 0 reflection 0.05 specular 1 roughness 0.001 irid { 0.65 thickness 0.8 } }
  interior { ior 1.45 }
  translate <0, -4, -0.5> }
