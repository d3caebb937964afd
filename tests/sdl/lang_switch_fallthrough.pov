// Once a clause matches, POV-Ray runs the following clauses too (whatever their
// conditions) until #break: here #range matches, then #case (5) and #else run as well.
#declare R = 0;
#switch (3)
  #case (1)
    #declare R = R + 1;
  #range (2, 4)
    #declare R = R + 10;
  #case (5)
    #declare R = R + 100;
  #else
    #declare R = R + 1000;
#end
sphere { <R, 0, 0>, 1.5 }
