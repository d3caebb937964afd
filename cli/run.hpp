// The lumen program: command line -> (per frame) interpret -> dump / check / render + write.
#pragma once
#include <string>
#include <vector>

#include "cli/options.hpp"

namespace lumen::cli {

// Everything main() does, for the arguments after the program name. Returns the exit status:
// 0 on success, 1 after printing a diagnostic (or, with --check, when features are missing).
int run_command_line(const std::vector<std::string>& args);

// Runs already-parsed options (on the calling thread). Throws LumenError.
int run_frames(const Options& o, SourceManager& sources);

}  // namespace lumen::cli
