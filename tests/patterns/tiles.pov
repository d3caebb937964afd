// POV-Ray 3.0's tiles { texture tile2 texture }: a checker of the two textures, the second
// where checker puts its first entry (measured).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 5, 0> look_at 0 right x * 4 up z * 3 }
plane { y, 0 texture { tiles { texture { pigment { rgb <1, 0.2, 0.1> } finish { ambient 1 diffuse 0 } } tile2 texture { pigment { rgb <0.1, 0.3, 1> } finish { ambient 1 diffuse 0 } } } scale 0.7 rotate y * 20 } }
