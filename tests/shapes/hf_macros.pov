// shapes.inc's height-field macros, whose HFCreate_ opens its mesh2 lists in one #if branch
// and closes them in another (decided when the macro is called), in a scene without #version:
// the include's `#version` restores leave 3.7 rules (sRGB output) in effect, as in POV-Ray.
#include "shapes.inc"

camera { location <0, 2.2, -3.2> look_at <0, 0.35, 0> angle 50 }
light_source { <3, 6, -4> color rgb 1 }
light_source { <-4, 3, -1> color rgb 0.3 }
background { rgb <0.2, 0.25, 0.3> }

#declare Wave = function(x, y, z) { 0.5 + 0.25 * sin(8 * x) * cos(6 * y) }

object {
    HF_Square(Wave, on, off, <24, 24>, on, "", <-1.6, 0, -0.2>, <-0.2, 0.5, 1.2>)
    pigment { rgb <0.9, 0.6, 0.3> }
}
object {
    HF_Sphere(Wave, on, off, <24, 24>, on, "", <0.1, 0.45, 0.3>, 0.3, 0.15)
    pigment { rgb <0.4, 0.8, 0.5> }
}
object {
    HF_Cylinder(Wave, on, off, <24, 12>, off, "", <1.1, 0, 0.4>, <1.1, 0.8, 0.4>, 0.25, 0.1)
    pigment { rgb <0.5, 0.6, 1> }
}
plane { y, 0 pigment { checker rgb 0.8 rgb 0.5 scale 0.5 } }
