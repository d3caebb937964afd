sphere { 0, 1 finish { reflection 0.3 } }
sphere { 0, 1 finish { reflection rgb <0.1, 0.2, 0.3> reflection_exponent 2 } }
sphere { 0, 1 finish { reflection { 0.1, 0.9 falloff 2 exponent 0.5 metallic 0.5 } } }
sphere { 0, 1 finish { reflection { 0.8 fresnel on } } }
