// A plain identifier argument is passed by reference: assigning the parameter (even with
// #local) changes the caller's variable. An expression argument is passed by value.
#macro AddTen(P) #declare P = P + 10; #end
#macro SetLocal(P) #local P = 99; #end
#declare A = 1;
AddTen(A)
#declare B = 2;
SetLocal(B)
#declare C = 3;
AddTen(C + 0)
sphere { <A, B, C>, 1.5 }
