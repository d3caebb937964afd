// An error inside an included file points into that file.
#include "lang_err_in_include.inc"
