#declare Ball = sphere { 0, 1 pigment { rgb <0, 0, 1> } }
object { Ball translate x*2 }
object { Ball scale 0.5 no_shadow }
object { Ball }
