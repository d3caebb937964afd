// Macros that produce the items of a block body: a centre and a radius.
#macro Centre(H) <0, H, 0>, #end
#macro Half(V) V / 2 #end
sphere { Centre(3) Half(5) }
