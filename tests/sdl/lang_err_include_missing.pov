// An include file that exists nowhere on the search path.
#include "no_such_file.inc"
