// #for counts from start to end inclusive with step 1; the variable ends one step past.
#for (K, 1, 3)
  sphere { <K, 0, 0>, K / 4 }
#end
sphere { <0, K, 0>, 1.5 }
