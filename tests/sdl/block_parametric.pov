// parametric: three functions of u and v, sorted uv corners, a sphere container, precompute.
parametric {
  function { cos(u) + v * cos(u / 2) * cos(u) }
  function { sin(u) + v * cos(u / 2) * sin(u) }
  function { v * sin(u / 2) }
  <2 * pi, 0.3>, <0, -0.3>
  contained_by { sphere { 0, 2 } }
  accuracy 0.002 max_gradient 1.5
  precompute 12, x, z
  pigment { rgb 1 }
}
