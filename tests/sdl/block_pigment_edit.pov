// A pigment { } or normal { } block that does not start from a declared one edits the pigment
// already there (POV-Ray 3.7): in a copied texture, after an earlier pigment in the same
// texture, and written on an object that has a texture. A block that starts from a declared
// pigment replaces it. Also rendered by tests/differential (identical to POV-Ray).
#version 3.7;
camera { location <0, 0, -4> look_at 0 }
light_source { <0, 5, -5> rgb 1 }
#declare P = pigment { checker rgb <1, 0, 0> rgb <0, 0, 1> }
#declare T = texture { pigment { P } finish { ambient 0.3 } }
box { <-2, -1, 0>, <-1, 1, 1> texture { T pigment { scale 0.5 } } }
box { <-1, -1, 0>, <0, 1, 1> texture { T } pigment { rgb <0, 1, 0> } }
box { <0, -1, 0>, <1, 1, 1> texture { pigment { P } pigment { rotate 45 * z } } }
box { <1, -1, 0>, <2, 1, 1> texture { T pigment { P scale 0.25 } } }
