// `lumen scene.pov [options] [file.ini ...]`: classifies each argument and handles the
// lumen-only long options (--help, --version, --dump-scene, --check, --threads N).
#pragma once
#include <string>
#include <vector>

#include "cli/options.hpp"

namespace lumen::cli {

// Parses the arguments after the program name. Throws LumenError on any bad argument. Checks
// that an input file was named unless --help or --version was given.
Options parse_command_line(const std::vector<std::string>& args, SourceManager& sources);

// One argument as POV-Ray reads it (also one word of an INI switch line): a switch, a
// Key=Value option, a *.pov input file, a library folder ending in '/', or an INI file.
void apply_argument(Options& o, SourceManager& sources, const std::string& word,
                    const SourceLoc& loc, int ini_depth = 0);

std::string usage_text();

}  // namespace lumen::cli
