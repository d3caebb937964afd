// The plane normal is normalised; the distance is not divided by its length.
plane { <0, 3, 4>, 2 }
plane { -y, 1 }
