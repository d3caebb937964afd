// #while makes one sphere per iteration.
#declare I = 0;
#while (I < 3)
  sphere { <I, I * I, 0>, 0.25 }
  #declare I = I + 1;
#end
