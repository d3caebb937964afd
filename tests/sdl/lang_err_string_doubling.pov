// A string doubled in a loop stops at the default string limit instead of taking gigabytes.
#declare S = "x";
#while (1) #declare S = concat(S, S); #end
