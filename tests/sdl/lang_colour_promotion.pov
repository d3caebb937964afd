// `color 0.5` sets all five channels (see-through); `rgb 0.5` leaves filter and transmit 0;
// a 4-component vector colour fills r, g, b and filter.
sphere { 0, 1 pigment { color 0.5 } }
sphere { x, 1 pigment { rgb 0.5 } }
sphere { y, 1 pigment { color <0.1, 0.2, 0.3, 0.4> } }
