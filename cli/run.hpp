// The lumen program: command line -> (per frame) interpret -> dump / check / render + write.
#pragma once
#include <string>
#include <vector>

#include <functional>
#include <memory>

#include "cli/frames.hpp"
#include "cli/options.hpp"

namespace lumen::cli {

// Everything main() does, for the arguments after the program name (`lumen merge ...` and
// `lumen farm ...` are subcommands: cli/merge.hpp, cli/farm.hpp). Returns the exit status:
// 0 on success, 1 after printing a diagnostic (or, with --check, when features are missing).
// main() says `process_ends`: the process exits when it returns.
int run_command_line(const std::vector<std::string>& args, bool process_ends = false);

// The scene of one frame as its render sees it: trace() and inside() through
// `object_queries`, pigment functions, #fopen beside the image, the Radiosity switch applied.
scene::Scene interpret_frame(const Options& o, const Frame& frame, SourceManager& sources,
                             const interp::WarningSink& warn,
                             const std::shared_ptr<scene::ObjectQueries>& object_queries);

// Runs `work` as main() does: on a big stack, with SIGINT/SIGTERM turned into stop requests,
// and every error printed as a diagnostic. Returns work's status, or 1 (128 + signal) after
// an error (a stop).
int run_guarded(const std::function<int(SourceManager&)>& work);

// Runs already-parsed options (on the calling thread). Throws LumenError.
int run_frames(const Options& o, SourceManager& sources);

}  // namespace lumen::cli
