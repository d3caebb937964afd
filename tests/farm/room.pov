// lumen farm's test scene: a small radiosity room seen by a camera that moves with the clock
// (so the solution is shared by every frame), an area light and textures that anti-aliasing
// refines, so that tiles and frame ranges have something to get wrong.
#version 3.7;
global_settings {
  assumed_gamma 1
  radiosity { count 40 recursion_limit 1 error_bound 0.5 }
}
camera { location <-0.8 + clock, 1.2, -1.9> look_at <0, 0.8, 0.5> angle 75 }
light_source { <0, 2.6, 0> rgb 1 area_light <0.5, 0, 0>, <0, 0, 0.5>, 2, 2 }
#declare Wall = texture { pigment { rgb 0.8 } finish { diffuse 0.8 ambient 0 } }
box { <-2, 0, -2>, <2, 3, 2> texture { Wall } hollow }
box { <-1.99, 0.01, -1.99>, <-1.95, 2.99, 1.99> pigment { rgb <0.8, 0.1, 0.1> } finish { ambient 0 } }
box { <1.95, 0.01, -1.99>, <1.99, 2.99, 1.99> pigment { rgb <0.1, 0.7, 0.1> } finish { ambient 0 } }
sphere { <0.3, 0.5, 0.2>, 0.5 pigment { checker rgb 1 rgb <0.2, 0.3, 0.8> scale 0.2 } finish { ambient 0 } }
