// #ifdef works on array elements: only initialised elements are defined.
#declare Slots = array[3];
#declare Slots[1] = 0.5;
#ifdef (Slots[1]) sphere { <1, 0, 0>, Slots[1] } #end
#ifdef (Slots[0]) sphere { <2, 0, 0>, 2 } #end
#ifndef (Slots[2]) sphere { <3, 0, 0>, 3 } #end
#ifdef (Nothing) sphere { <4, 0, 0>, 4 } #end
