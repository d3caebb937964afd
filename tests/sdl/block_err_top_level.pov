#declare P = pigment { rgb 1 }
sphere { 0, 1 }
P
