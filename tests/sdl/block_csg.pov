// Children without a texture inherit the CSG's (their texture stays empty); the CSG's
// transform moves the children's own textures too.
difference {
  box { -1, 1 }
  union {
    sphere { 0, 1.2 pigment { checker } }
    cylinder { -2*x, 2*x, 0.5 }
  }
  pigment { rgb <1, 1, 0> }
  translate y*2
}
merge { sphere { 0, 1 } sphere { x, 1 } }
intersection { sphere { 0, 1 } box { 0, 2 } inverse }
