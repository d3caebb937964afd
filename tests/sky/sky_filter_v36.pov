// Under #version 3.6 POV-Ray layers a sky_sphere's pigments with filter taken as transmit
// (3.7 filters): a filtered gradient and a filtered, transmitting bozo over a blue layer.
#version 3.6;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0.5, -4> right x*4/3 up y angle 90 look_at <0, 1.5, 0> }
sky_sphere {
  pigment { rgb <0.4, 0.6, 0.9> }
  pigment { gradient x color_map { [0 rgbf <0.75, 0.5, 0.25, 0.1>] [1 rgbf <1, 1, 1, 1>] }
            translate x*0.5 scale 2 }
  pigment { bozo turbulence 0.6 octaves 7 omega 0.49876 lambda 2.5432
            color_map { [0 rgbft <0.2, 0.9, 0.5, 0.3, 0.2>] [0.5 rgbf <0.9, 0.9, 0.9, 0.9>]
                        [0.7 rgbf 1] } scale <0.6, 0.18, 0.18> }
}
