// Comparisons give 1 or 0; = and != compare within POV's EPSILON (1e-10).
#declare A = (1 < 2) + (2 <= 2) + (3 >= 4) + (1 != 1);
#declare B = (1e-11 = 0);
#declare C = (0.1 + 0.2 = 0.3);
#declare D = !(2 > 1);
sphere { <A, B, C>, D + 0.5 }
