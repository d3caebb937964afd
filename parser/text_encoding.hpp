// Refuses input that is not SDL text before the grammar sees it: a binary file (an image
// #included by mistake) or UTF-16/UTF-32 text (as some Windows editors save). Probed with
// POV-Ray 3.7: it reads such files byte by byte and stops with "Illegal character in input
// file" or a syntax error about the second byte of a UTF-16 file. A UTF-8 byte order mark is
// fine (the grammar skips it; POV-Ray accepts it in the scene file, though not in an include).
#pragma once
#include "base/source.hpp"

namespace lumen::parser {

// Throws LumenError at the file's first line: "... is UTF-16 text ..." or "... binary ...".
void check_sdl_text(const SourceFile& file);

}  // namespace lumen::parser
