// Precedence: unary minus, then * /, then + -, then comparisons, then & |.
// (As in POV-Ray, a comparison in #declare needs parentheses.)
#declare A = 1 + 2 * 3 - 4 / 2;
#declare B = 10 - 2 - 3;
#declare C = -2 * -3;
#declare D = (2 * 3 + 4 * 5 > 25 & 1);
sphere { <A, B, C>, D / 2 }
