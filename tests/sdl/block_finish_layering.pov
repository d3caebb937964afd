// A finish block applies on top of the finish in place; a declared finish replaces it whole.
#declare F = finish { specular 0.5 }
#declare T = texture { pigment { rgb 1 } finish { ambient 0.3 phong 1 } }
sphere { 0, 1 texture { T finish { phong 0.5 } } }
sphere { 0, 1 texture { T } finish { diffuse 0.8 } }
sphere { 0, 1 texture { T finish { F } } }
