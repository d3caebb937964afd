#default { finish { ambient 0.3 diffuse 0.5 } }
sphere { 0, 1 pigment { rgb 1 } }
#default { pigment { rgb <1, 0, 0> } }
sphere { 0, 1 texture { finish { phong 1 } } }
