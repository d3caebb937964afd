#declare S = "x";
#while (1) #declare S = concat(S, S); #end
