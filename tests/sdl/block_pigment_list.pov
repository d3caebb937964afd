sphere { 0, 1 pigment { checker rgb <1, 0, 0>, rgb <0, 0, 1> scale 0.25 } }
sphere { 0, 1 pigment { hexagon color rgb 1, color rgb 0.5, color rgb 0 } }
sphere { 0, 1 pigment { brick rgb 0.5, rgb <0.6, 0.2, 0.1> brick_size <2, 1, 1> mortar 0.1 } }
sphere { 0, 1 pigment { checker pigment { rgb 1 } pigment { gradient x } } }
