// Directives may appear between the items of a block: #if chooses the radius.
#declare Big = 1;
sphere {
  <1, 2, 3>,
  #if (Big)
    2.5
  #else
    0.5
  #end
}
