// #break ends the #switch; a selector matching no clause runs #else.
#macro Pick(N)
  #switch (N)
    #case (1)
      sphere { <N, 1, 0>, 0.1 }
      #break
    #range (2, 3)
      sphere { <N, 2, 0>, 0.2 }
      #break
    #else
      sphere { <N, 3, 0>, 0.3 }
  #end
#end
Pick(1)
Pick(2.5)
Pick(7)
