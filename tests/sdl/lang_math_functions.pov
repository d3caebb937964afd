// Rounding and remainder functions behave like POV-Ray's: int truncates, mod keeps the sign.
sphere { <mod(-7, 3), div(-7, 2), int(-2.5)>, 0.5 }
sphere { <floor(-2.5), ceil(-2.5), abs(-3)>, sqrt(16) / 8 }
sphere { <pow(2, 3), degrees(pi), log(1000)>, 0.5 }
