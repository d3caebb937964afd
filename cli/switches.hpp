// POV-Ray style switches: +X[param] turns X on (or sets it), -X turns it off.
#pragma once
#include <string>

#include "cli/options.hpp"

namespace lumen::cli {

// Applies one switch argument such as "+W640", "-A", "+A0.1", "+FN16" or "+KFI1" by translating
// it to INI options. Throws LumenError at `loc` for an unknown switch (with a suggestion), a
// missing parameter, or a parameter given to a switch that takes none.
void apply_switch(Options& o, SourceManager& sources, const std::string& arg, const SourceLoc& loc,
                  int ini_depth = 0);

// The switch names, for --help and suggestions (e.g. "W", "AM", "KFI").
std::string switch_help();

}  // namespace lumen::cli
