sphere { 0, 1
  hollow no_shadow no_image no_reflection double_illuminate no_radiosity
  clipped_by { plane { y, 0.5 } }
  bounded_by { clipped_by }
  translate x
}
sphere { 0, 1 hollow off no_image off }
