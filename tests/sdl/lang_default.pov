// #default changes the finish given to later textures.
#default { finish { ambient 0.3 diffuse 0.5 } }
sphere { 0, 1 pigment { rgb <1, 0, 0> } }
