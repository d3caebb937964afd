// str() and vstr() format like printf; string lengths show the padding.
#declare A = str(2.5, 6, 2);      // "  2.50"
#declare B = str(1.23456, -8, 2); // "00001.23"
#declare C = vstr(3, <1, 2, 3>, ", ", 0, 1);  // "1.0, 2.0, 3.0"
#declare D = str(7, 0, -1);       // "7.000000"
sphere { <strlen(A), strlen(B), strlen(C)>, strlen(D) / 16 }
sphere { <val(substr(B, 1, 5)), val(substr(C, 6, 3)), 0>, 0.5 }
