// A 2-component vector has no .z.
#declare P = <1, 2>;
sphere { <0, 0, 0>, P.z }
