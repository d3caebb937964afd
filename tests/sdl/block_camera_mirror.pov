// A left-handed right vector mirrors the image: look_at keeps its sign.
camera { right -x*1.33 location <0, 0, -3> look_at <1, 0, 0> }
