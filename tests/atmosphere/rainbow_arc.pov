// rainbow { arc_angle falloff_angle }: partial arcs. One spans 200 degrees around an oblique
// up vector and fades over its last 75 degrees at each end into the sky and the ground; one,
// over a mirror sphere, is a hard-ended 90-degree arc (falloff_angle defaults to arc_angle).
// No jitter: POV-Ray's render is matched exactly.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -10> look_at <0, 2, 0> angle 80 }
light_source { <-20, 30, -20> rgb 1 }
background { rgb <0.45, 0.6, 0.85> }
rainbow {
  angle 30 width 8 direction <0.1, -0.3, 1> up <1, 1, 0.3> arc_angle 200 falloff_angle 50
  colour_map {
    [0.0 rgb <0.6, 0.2, 1> filter 1]
    [0.3 rgb <0.2, 0.3, 1> filter 0.6]
    [0.6 rgb <0.2, 1, 0.3> transmit 0.2]
    [1.0 rgb <1, 0.2, 0.1> transmit 1]
  }
}
rainbow {
  angle 12 width 6 distance 40 direction <-0.2, 0.1, 1> up -x arc_angle 90
  colour_map { [0 rgb <1, 1, 1> transmit 1] [0.5 rgb <1, 0.5, 0.2> transmit 0.3] [1 rgb 1 transmit 1] }
}
plane { y, 0 pigment { checker rgb 0.8 rgb 0.3 scale 2 } }
sphere { <3, 2, 4>, 2 pigment { rgb 0.1 } finish { reflection 0.8 specular 0.5 } }
