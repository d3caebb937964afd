// File I/O: a write outside the working folder is refused where it stands.
#declare A = 1;
#fopen Log "../log.txt" write
