// String functions turned into numbers: strlen, substr, strupr, val, asc, strcmp, concat.
#declare S = concat("ab", "cde", chr(70));
#declare Up = strupr(substr(S, 2, 3));
sphere { <strlen(S), asc(Up) - 64, strcmp(Up, "BCD")>, val("0.75") }
sphere { <strcmp("b", "a"), strcmp("x", "x"), val("3.5e1xyz")>, strlen(strlwr("ABC")) / 4 }
