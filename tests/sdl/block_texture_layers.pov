#declare Base = texture { pigment { rgb 1 } finish { phong 1 } }
// Each texture adds a layer on top; a declared texture is copied and may be modified.
sphere { 0, 1
  texture { Base }
  texture { Base finish { phong 0.5 } pigment { rgbt <1, 0, 0, 0.5> } }
}
// A pigment written straight on an object modifies its (default) texture.
sphere { 0, 1 pigment { rgb <0, 1, 0> } finish { ambient 0.2 } }
