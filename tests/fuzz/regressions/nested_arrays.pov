#declare A = array[1000];
#for (I, 0, 999) #declare A[I] = array[1000]; #end
