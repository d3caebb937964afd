// angle sets the direction length from right; sky tilts up; right x*4/3 keeps handedness.
camera { right x*4/3 sky <0.2, 1, 0> angle 60 location <0, 0, -4> look_at 0 }
