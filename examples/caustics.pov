// Caustics by photon mapping: a glass sphere and a glass of water focus a spotlight onto a
// table, a tinted glass lens colours its caustic, and a curved mirror throws a bright line on
// the table. Renders as POV-Ray 3.7 does (tests/differential).
#version 3.7;
global_settings {
  assumed_gamma 1
  max_trace_level 10
  photons { spacing 0.008 autostop 0 }
}
camera { location <0, 3.2, -6> look_at <0, 0.6, 0.4> angle 42 }
background { rgb <0.05, 0.06, 0.08> }
light_source { <-0.8, 4.5, 4.5> rgb 1.5 spotlight point_at <0.2, 0, -0.4> radius 24 falloff 32
               photons { refraction on reflection on } }
light_source { <4, 5, -6> rgb 0.15 shadowless }
// The table and the wall behind it collect photons.
plane { y, 0 pigment { checker rgb 0.85 rgb 0.65 scale 0.6 } finish { diffuse 0.8 ambient 0.04 } }
plane { z, 6 pigment { rgb <0.8, 0.78, 0.72> } finish { diffuse 0.8 ambient 0.04 } }
#declare Glass = material {
  texture { pigment { rgbf <0.98, 0.99, 1, 0.97> } finish { ambient 0 diffuse 0 specular 0.6 roughness 0.005 reflection { 0.04, 1 fresnel } conserve_energy } }
  interior { ior 1.5 }
}
sphere { <-1.3, 0.55, 0.3>, 0.55 material { Glass } photons { target refraction on reflection on collect off } }
// A glass of water: the glass as a hollow cylinder, the water inside it.
union {
  difference {
    cylinder { <0, 0.001, 0>, <0, 1.2, 0>, 0.42 }
    cylinder { <0, 0.08, 0>, <0, 1.3, 0>, 0.38 }
    material { Glass }
  }
  cylinder { <0, 0.08, 0>, <0, 0.8, 0>, 0.379
    texture { pigment { rgbf <0.9, 0.97, 1, 0.95> } finish { ambient 0 diffuse 0 reflection { 0.02, 1 fresnel } conserve_energy } }
    interior { ior 1.33 }
  }
  photons { target refraction on reflection on collect off }
  translate <0.35, 0, 0.5>
}
// A tinted lens.
sphere { 0, 1 scale <0.45, 0.45, 0.15> rotate <-35, 25, 0> translate <1.5, 0.5, 0.2>
  material { texture { pigment { rgbf <1, 0.55, 0.2, 0.85> } finish { ambient 0 diffuse 0 phong 0.5 } } interior { ior 1.45 } }
  photons { target refraction on collect off }
}
// A curved mirror: part of a tube facing the light, its caustic a bright cusp on the table.
difference {
  cylinder { <0, 0.002, 0>, <0, 0.3, 0>, 0.9 }
  cylinder { <0, -0.1, 0>, <0, 0.4, 0>, 0.88 }
  plane { z, 0.3 }
  pigment { rgb <0.95, 0.9, 0.75> } finish { reflection 0.85 diffuse 0.05 ambient 0 metallic }
  photons { target reflection on }
  rotate y * 200 translate <-0.2, 0, -0.2>
}
