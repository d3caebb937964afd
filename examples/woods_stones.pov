// Woods and stones from POV-Ray's include files, unmodified: six woods.inc textures on
// planks, four stones1.inc/stones2.inc granites and a textures.inc Jade sphere, lit by one
// light so the noise patterns' detail (wood rings, turbulence, granite grains) shows.
#version 3.7;
global_settings { assumed_gamma 1.0 }

#include "colors.inc"
#include "textures.inc"
#include "woods.inc"
#include "stones.inc"

camera {
  location <0, 3.2, -7.5>
  look_at  <0, 0.6, 0>
  right x*image_width/image_height
  angle 52
}
light_source { <-6, 12, -10> color rgb 1.1 }
light_source { <8, 6, -4> color rgb 0.35 shadowless }
background { color rgb <0.55, 0.62, 0.75> }

#declare Plank = box { <-0.45, 0, -2>, <0.45, 0.2, 2> }
#macro Wood_plank(X, T)
  object { Plank texture { T } translate x*X }
#end
Wood_plank(-2.5, T_Wood1)
Wood_plank(-1.5, T_Wood7)
Wood_plank(-0.5, T_Wood10)
Wood_plank(0.5, T_Wood14)
Wood_plank(1.5, T_Wood19)
Wood_plank(2.5, T_Wood23)

#declare Block = box { <-0.55, 0, -0.55>, <0.55, 1.1, 0.55> }
object { Block texture { T_Grnt5 } translate <-2.4, 0.2, 2.6> }
object { Block texture { T_Grnt15 } rotate y*20 translate <-1, 0.2, 3.0> }
object { Block texture { T_Stone8 } rotate -y*15 translate <1, 0.2, 3.0> }
object { Block texture { T_Stone24 } translate <2.4, 0.2, 2.6> }
sphere { <0, 0.9, 0.6>, 0.7 texture { Jade } }
