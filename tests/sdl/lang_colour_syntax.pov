// Colour parts apply in the order written: rgbf/rgbt/rgbft, then single channels.
#declare Base = rgbft <1, 0, 0, 0.2, 0.2>;
sphere { 0, 1 pigment { rgbf <0.1, 0.2, 0.3, 0.4> } }
sphere { x, 1 pigment { rgbt <0.1, 0.2, 0.3, 0.4> } }
sphere { y, 1 pigment { rgb 1 filter 0.25 red 0.5 } }
sphere { z, 1 pigment { color Base filter 0.5 } }
