sphere { 0, 1
  finish {
    ambient rgb <0.1, 0.2, 0.3> emission 0.5 diffuse 0.7, 0.2 brilliance 2
    phong 0.4 phong_size 60 specular 0.3 roughness 0.01 metallic crand 0.05
    conserve_energy irid { 0.25 thickness 0.5 turbulence 0.1 } ior 1.5
  }
}
// albedo uses the final brilliance / phong_size.
sphere { 0, 1 finish { diffuse albedo 0.5 brilliance 3 phong albedo 0.2 phong_size 9 } }
