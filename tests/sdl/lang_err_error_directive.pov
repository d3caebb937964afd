// #error stops with the user's message.
#declare Count = 3;
#if (Count > 2)
  #error concat("too many: ", str(Count, 0, 0))
#end
