// #break leaves the innermost loop; a #switch inside the loop keeps its own #break.
#declare I = 0;
#while (1)
  #declare I = I + 1;
  #switch (I)
    #case (2)
      #break
    #else
      sphere { <I, 0, 0>, 0.5 }
  #end
  #if (I = 3)
    #break
  #end
#end
sphere { <0, I, 0>, 2 }
