// An inverted union of overlapping cylinders cut out of a box (qtvr/qtvrpanorama.pov's hollow
// box), seen from outside and through the hole, and a union subtracted from a box: POV-Ray
// leaves no inner walls in the holes.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <3, 4, -5> look_at 0 angle 40 }
light_source { <-100, 50, -50> color rgb 1 }
#declare CylinderCluster = union
{
  cylinder {-z,+z,1}
  cylinder {-z,+z,1 translate -x-y}
  cylinder {-z,+z,1 translate +x-y}
  cylinder {-z,+z,1 translate -x+y}
  cylinder {-z,+z,1 translate +x+y}
  scale <0.4, 0.4, 1.1>
}

#declare HollowBox = intersection
{
  box {-1, +1}
  object {CylinderCluster inverse}
  object {CylinderCluster rotate 90*y inverse}
  object {CylinderCluster rotate 90*x inverse}
}

object { HollowBox pigment { rgb 1 } }
object { HollowBox pigment { rgb <1, 0.7, 0.4> } scale 0.5 translate <-1.4, 0, 1> }
difference { box { -0.6, 0.6 } union { sphere { <0.25, 0.6, 0>, 0.4 } sphere { <-0.2, 0.6, 0>, 0.4 } } pigment { rgb <0.5, 0.8, 1> } translate <1.5, -0.6, -0.5> }
