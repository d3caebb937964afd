// A #for loop with step 0 would never end.
#for (I, 0, 10, 0)
  sphere { <I, 0, 0>, 1 }
#end
