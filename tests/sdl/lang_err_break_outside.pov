// #break outside #switch, #while, #for or a macro.
#declare A = 1;
#if (A)
  #break
#end
