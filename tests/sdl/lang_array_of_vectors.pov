// Arrays hold any value: here vectors, read back in a #while loop.
#declare Points = array[3] {<1, 0, 0>, <0, 2, 0>, <0, 0, 3>};
#declare I = 0;
#while (I < 3)
  sphere { Points[I] * 2, 0.5 }
  #declare I = I + 1;
#end
