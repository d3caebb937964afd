// POV-Ray 3.7's internal fonts 0-3 and an out-of-range number (font 0), numbers truncated.
#include "text_common.inc"
text { internal 1 "Rg1" 0.3, 0 pigment { rgb <1, 0.8, 0.2> } translate <-0.2, 1.2, 0> }
text { internal 2.7 "OB" 0.3, 0 pigment { rgb <0.6, 0.9, 1> } translate <1.8, 1.2, 0> }
text { internal 3 "Gl" 0.3, 0 pigment { rgb <0.9, 0.5, 0.5> } translate <-0.2, 0, 0> }
text { internal 0 "P" 0.3, 0 pigment { rgb <0.8, 0.2, 0.9> } translate <1.8, 0, 0> }
text { internal 9 "P" 0.3, 0 pigment { rgb 0.9 } rotate <0, 30, 0> translate <3, 0, 0> }
