// Pigment patterns with color_maps: checker, gradient, brick, hexagon, onion and radial,
// one per tile, lit flat so the colours show as mapped.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 0, -7>
  look_at  <0, 0, 0>
  right x*image_width/image_height
  angle 50
}

light_source { <0, 0, -20> color rgb 1 }
background { color rgb 0.1 }

#default { finish { ambient 0.3 diffuse 0.7 } }

#declare Tile = box { <-1, -1, 0>, <1, 1, 0.1> }

object { Tile translate <-2.2, 1.1, 0>
  pigment { checker color rgb <1, 0.9, 0.2> color rgb <0.1, 0.2, 0.6> scale 0.4 }
}
object { Tile translate <0, 1.1, 0>
  pigment { gradient x
    color_map { [0 color rgb <1, 0, 0>] [0.5 color rgb <0, 1, 0>] [1 color rgb <0, 0, 1>] }
    scale 2 translate -x
  }
}
object { Tile translate <2.2, 1.1, 0>
  pigment { brick color rgb 0.8 color rgb <0.7, 0.25, 0.1> brick_size <0.5, 0.2, 0.5> mortar 0.04 }
}
object { Tile translate <-2.2, -1.1, 0>
  pigment { hexagon color rgb <0.9, 0.1, 0.1> color rgb <0.1, 0.9, 0.1> color rgb <0.1, 0.1, 0.9>
    rotate x*90 scale 0.3 }
}
object { Tile translate <0, -1.1, 0>
  pigment { onion
    color_map { [0 color rgb <1, 1, 1>] [0.5 color rgb <0.9, 0.5, 0>] [1 color rgb <0.2, 0, 0.4>] }
    scale 0.5
  }
}
object { Tile translate <2.2, -1.1, 0>
  pigment { radial frequency 8
    color_map { [0 color rgb <0, 0.3, 0.8>] [0.5 color rgb <1, 1, 1>] [1 color rgb <0, 0.3, 0.8>] }
    rotate x*90
  }
}
