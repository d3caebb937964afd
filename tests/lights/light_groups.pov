// light_group: a group's lights light only its members (red here), and its members get the
// scene's lights (blue) only with `global_lights on` (off by default). Anything casts
// shadows from a group's light (the bar above the left sphere is outside its group). One
// declared group placed twice is two groups. A group inside a group lights its members with
// its own lights only, and they get the scene's lights only where both groups say
// global_lights on; a light in a plain union inside a group lights the whole scene. A negative
// light darkens (advanced/abyss.pov's mines). All as POV-Ray 3.7 renders it (probed).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at 0 right x * 12 up y * 6 }
#declare Matte = texture { pigment { rgb 1 } finish { ambient 0.1 diffuse 0.8 } }
plane { z, 2 texture { Matte } }
light_source { <20, 30, -40> rgb <0, 0.3, 1> }
box { <-5.5, 1.1, -2>, <-4, 1.2, 0> texture { Matte } }  // shadows the first sphere's top
light_group {
  light_source { <-4, 40, -10> rgb <1, 0, 0> }
  sphere { <-4.5, 0, 0>, 1 texture { Matte } }
}
light_group {
  light_source { <-10, 10, -30> rgb <1, 0.2, 0> }
  sphere { <-2, 0, 0>, 1 texture { Matte } }
  global_lights on
}
#declare Pair = light_group {
  light_source { <0, 0, -30> rgb <1, 0.6, 0> translate x * -4 }
  box { <-0.6, -2.6, -0.6>, <0.6, -1.4, 0.6> texture { Matte } }
  global_lights
}
object { Pair translate x * 0.5 }
object { Pair translate x * 2.5 rotate z * 10 }
light_group {
  light_source { <30, 0, -20> rgb <0, 1, 0> }
  sphere { <2, 1.2, 0>, 0.9 texture { Matte } }
  light_group {
    light_source { <0, 30, -20> rgb <0.8, 0, 0.8> shadowless }
    union {
      light_source { <5, -30, -20> rgb <0.5, 0.5, 0.5> }  // in a union in the inner group
      sphere { <4.5, 0.5, 0>, 1 texture { Matte } }
    }
    global_lights on
  }
}
light_group {
  sphere { <4.5, -2, 0>, 0.8 texture { Matte } }
  light_source { <0, 0, -30> rgb -0.5 shadowless }  // negative: darker than the blue alone
  global_lights on
}
