// Render benchmark for text (bench/render_vs_povray.sh build/lumen 2 3 bench/text.pov): four
// lines of extruded TrueType text, two fonts of POV-Ray's include folder (timrom.ttf with its
// straight and curved edges, crystal.ttf), filling the view and tilted so the rays meet the
// faces and the side walls, with shadows and a reflective floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -9> look_at <0, 0.6, 0> angle 58 }
light_source { <-8, 12, -12> rgb 1 }
light_source { <8, 6, -6> rgb 0.4 }
background { rgb <0.15, 0.18, 0.25> }
plane { y, -2.6 pigment { checker rgb 0.8 rgb 0.5 } finish { reflection 0.2 } }
#macro Line(Font, Words, Depth, Y, Colour, Tilt)
  #local T = text { ttf Font Words Depth, 0 }
  #local W = max_extent(T).x - min_extent(T).x;
  object { T translate -W / 2 * x scale <8.6 / W, 1.4, 1>
    pigment { rgb Colour } finish { phong 0.5 }
    rotate Tilt translate Y * y }
#end
Line("timrom.ttf", "Quick brown foxes jump", 0.5, 2.9, <1, 0.6, 0.3>, <-15, 10, 0>)
Line("crystal.ttf", "over the lazy dogs", 0.8, 1.2, <0.4, 0.8, 0.5>, <-10, -8, 0>)
Line("timrom.ttf", "SPHINX OF BLACK QUARTZ", 0.3, -0.4, <0.4, 0.6, 1>, <-5, 6, 2>)
Line("crystal.ttf", "judge my vow 0123456789", 1.2, -2.0, <1, 0.9, 0.4>, <20, -12, 0>)
