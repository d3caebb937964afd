// A pigment_map's entries are evaluated at the parent's pattern point: the parent's
// turbulence bends the checker too.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
plane { z, 0.37
  pigment { gradient x
    pigment_map { [0 checker rgb 0 rgb 1 scale 0.2] [1 rgb <1, 0, 0>] }
    turbulence 0.5 scale 2 }
  finish { ambient 1 diffuse 0 }
}
