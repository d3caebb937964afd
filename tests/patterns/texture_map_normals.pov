// A texture_map's entries' normals are perturbed in the map's space: the map's rotation turns
// them (POV warps them through the map's transforms).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
light_source { <-1000, 1500, -2000> rgb 1 parallel point_at 0 }
plane { z, 0.37
  texture { gradient x
    texture_map {
      [0 pigment { rgb 1 } normal { bumps 0.8 scale 0.2 } finish { ambient 0 diffuse 1 }]
      [1 pigment { rgb <1, 0.5, 0.3> } normal { wood 0.5 scale 0.3 } finish { ambient 0 diffuse 1 }]
    }
    scale 2 rotate z*40 }
}
