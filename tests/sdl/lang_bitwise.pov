// Bitwise functions work on integers.
sphere { <bitwise_and(12, 10), bitwise_or(12, 10), bitwise_xor(12, 10)>, 0.5 }
