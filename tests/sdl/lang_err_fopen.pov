// File I/O directives are refused where they stand.
#declare A = 1;
#fopen Log "log.txt" write
