// INI files (POV-Ray 3.7's rules): Key=Value lines, switch lines, file names, comments,
// [Section] headers, and "file.ini[Section]" to select a section.
#pragma once
#include <string>

#include "cli/options.hpp"

namespace lumen::cli {

// Reads `spec` ("file.ini" or "file.ini[Section]") and applies it to `o`. Lines before the first
// [Section] header always apply; lines under a header apply only when that section was named.
// `depth` counts Include_Ini nesting. Throws LumenError (at `from` when the file is missing).
void read_ini_file(Options& o, SourceManager& sources, const std::string& spec,
                   const SourceLoc& from, int depth = 0);

// Applies the text of an INI file already loaded into `sources` (tests use this directly).
void apply_ini_text(Options& o, SourceManager& sources, const SourceFile& file,
                    const std::string& section, int depth = 0);

// Splits "file.ini[Section]" into the file and the section (empty when none).
std::pair<std::string, std::string> split_ini_spec(const std::string& spec);

}  // namespace lumen::cli
