// Features that parse but are not rendered yet are listed in source order (media render).
sphere { 0, 1 pigment { granite } }
sphere { 0, 1 hollow interior { media { emission 0.5 } } pigment { facets } }
camera { fisheye angle 180 }
union { lemon { <0, 0, 0>, <0, 1, 0>, 1, 0.5 } sphere { 0, 1 } }
