// seed() starts a stream and rand() steps it: the same sequence as POV-Ray 3.7.
#declare S = seed(42);
#declare A = rand(S);
#declare B = rand(S);
#declare T = seed(0);
sphere { <A, B, rand(T)>, 0.5 }
