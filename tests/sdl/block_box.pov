// Box corners are reordered per axis.
box { <1, -2, 3>, <-1, 2, -3> }
