// A recursive macro used in an expression must produce exactly one value.
#macro Fact(N)
  #if (N <= 1)
    1
  #else
    N * Fact(N - 1)
  #end
#end
sphere { <Fact(3), Fact(4), Fact(5)>, Fact(1) / 4 }
