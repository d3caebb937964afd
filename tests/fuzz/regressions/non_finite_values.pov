#declare R = 1/0;
sphere { <0/0, 1e400, -1/0>, R scale <1, acos(2), 1> }
box { -exp(1000), mod(1, 0) }
