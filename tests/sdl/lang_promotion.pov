// A float used with a vector stands for a vector with all components equal; vectors of
// different sizes are padded with zeros. Scalars promote in object arguments too.
#declare V = <1, 2, 3> + 1;
#declare W = 2 * <1, 2, 3>;
#declare U = <1, 2> + <1, 2, 3>;
sphere { V, 0.5 }
sphere { W, 0.5 }
sphere { U, 0.5 }
sphere { 3, 0.5 }
