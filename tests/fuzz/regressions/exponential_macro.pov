#macro M(N) #if (N > 0) M(N - 1) M(N - 1) #end #end
M(60)
