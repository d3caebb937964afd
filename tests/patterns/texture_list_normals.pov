// The list form of a texture pattern (checker texture{} texture{}): its entries' normals are
// perturbed in the pattern's rotated, non-uniformly scaled space.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> direction z right 4*x up 3*y }
light_source { <-1000, 1500, -2000> rgb 1 parallel point_at 0 }
plane { z, 0.37
  texture { checker
     texture { pigment { rgb 1 } normal { bumps 0.8 scale 0.2 } finish { ambient 0 diffuse 1 } }
     texture { pigment { rgb <1, 0.5, 0.3> } normal { wood 0.8 scale 0.3 } finish { ambient 0 diffuse 1 } }
    rotate z*30 scale <0.7, 0.5, 1> }
}
