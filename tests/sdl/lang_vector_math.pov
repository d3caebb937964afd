// Vector functions: vcross, vdot, vlength, vnormalize.
#declare A = <1, 0, 0>;
#declare B = <0, 1, 0>;
sphere { vcross(A, B), vdot(<1, 2, 3>, <4, 5, 6>) / 8 }
sphere { vnormalize(<3, 0, 4>), vlength(<3, 4, 0>) }
