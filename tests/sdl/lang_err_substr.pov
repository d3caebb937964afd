// substr() outside the string.
#declare S = "abc";
#declare T = substr(S, 2, 5);
