// #if / #elseif / #else pick exactly one branch, checked in order.
#declare Mode = 2;
#if (Mode = 1)
  sphere { <1, 0, 0>, 1.5 }
#elseif (Mode = 2)
  sphere { <2, 0, 0>, 2.5 }
#elseif (Mode >= 2)
  sphere { <3, 0, 0>, 3.5 }
#else
  sphere { <4, 0, 0>, 4.5 }
#end
#if (Mode < 0)
  sphere { <5, 0, 0>, 5.5 }
#else
  sphere { <6, 0, 0>, 6.5 }
#end
