// Jitter check for the differential suite (tests/differential/scenes.txt): as probe.pov, one
// pixel is one world unit, but red and green are triangle waves in x and y with a period of
// one pixel (continuous, so no sample sits on a jump where rounding could flip it), pixel
// centres half-way up a slope. Rendered with +A0.0 every pixel is supersampled, and its
// colour is the mean of where its jittered samples fell: a wrong jitter offset shows at once.
#version 3.7;
global_settings { assumed_gamma 1 }
camera {
  orthographic
  location <image_width / 2, image_height / 2, -10>
  look_at <image_width / 2, image_height / 2, 0>
  right x * image_width
  up y * image_height
}
// Red: the wave in x. Green: a pigment_map in y blends the same red wave with and without
// green, so green is the wave in y.
#declare Red = pigment { gradient x colour_map { [0 rgb 0] [0.5 rgb <1, 0, 0>] [1 rgb 0] } translate x * 0.25 }
#declare RedGreen = pigment { gradient x colour_map { [0 rgb <0, 1, 0>] [0.5 rgb <1, 1, 0>] [1 rgb <0, 1, 0>] } translate x * 0.25 }
plane { -z, 0
  pigment { gradient y pigment_map { [0 Red] [0.5 RedGreen] [1 Red] } translate y * 0.25 }
  finish { ambient 1 diffuse 0 specular 0 phong 0 }
}
