// A macro used in an expression must produce exactly one value.
#macro Pair() 1, 2 #end
#declare A = Pair();
