// A macro called at item level splices its items where it is called.
#macro Ball(P, R)
  sphere { P, R }
#end
Ball(<1, 2, 3>, 0.5)
Ball(x * 4, 1.5)
