// Normal patterns and warps: bumps, dents, wrinkles, ripples, waves and a bozo normal on a
// row of spheres, a quilted floor, and warped pigments (repeat with flip, black_hole,
// turbulence warps interleaved with transforms, a spherical mapping warp) on three panels.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 2.4, -8.5>
  look_at  <0, 0.9, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-5, 9, -8> color rgb 1 }
light_source { <6, 4, -6> color rgb 0.3 }
background { color rgb <0.3, 0.35, 0.45> }

plane { y, 0
  pigment { color rgb <0.75, 0.7, 0.6> }
  normal { quilted 0.6 control0 0.2 control1 0.9 scale 1.2 }
  finish { specular 0.3 }
}

#declare Shiny = finish { phong 0.8 phong_size 60 reflection 0.08 }
#macro Ball(X, N)
  sphere { <X, 0.55, -1.2>, 0.5 pigment { color rgb <0.85, 0.45, 0.2> } normal { N } finish { Shiny } }
#end
Ball(-3.0, normal { bumps 0.8 scale 0.12 })
Ball(-1.8, normal { dents 1.5 scale 0.2 })
Ball(-0.6, normal { wrinkles 1 scale 0.3 })
Ball(0.6, normal { ripples 1.2 frequency 8 scale 0.4 })
Ball(1.8, normal { waves 0.8 frequency 6 scale 0.5 })
Ball(3.0, normal { bozo 2 scale 0.15 turbulence 0.3 })

#declare Panel = box { <-1, 0, 0>, <1, 2, 0.1> }
object { Panel
  pigment { gradient x color_map { [0 rgb <0.1, 0.2, 0.7>] [0.5 rgb <0.9, 0.9, 0.3>] [1 rgb <0.7, 0.1, 0.1>] }
    warp { repeat x*0.5 flip x }
    warp { turbulence 0.15 octaves 3 }
    scale 0.8 }
  translate <-2.3, 0.2, 1.5>
}
object { Panel
  pigment { checker color rgb 0.95 color rgb <0.2, 0.3, 0.25>
    scale 0.25
    warp { black_hole <0, 1, 0>, 0.8 falloff 1.5 strength 2.5 }
  }
  translate <0, 0.2, 1.5>
}
object { Panel
  pigment { brick color rgb 0.85 color rgb <0.6, 0.2, 0.1> brick_size <0.4, 0.15, 0.4> mortar 0.03
    warp { turbulence <0.2, 0.1, 0> lambda 2.5 omega 0.6 }
    rotate z*10
  }
  translate <2.3, 0.2, 1.5>
}
