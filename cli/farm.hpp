// `lumen farm [farm options] scene.pov [lumen options]`: one render cut into parts that run
// as separate lumen processes, on this machine or as Slurm jobs, and put back together into
// the files a single `lumen` run would write, byte for byte (docs in README "Render farms").
#pragma once
#include <string>
#include <vector>

namespace lumen::cli {

// Returns the exit status.
int run_farm(const std::vector<std::string>& args);

}  // namespace lumen::cli
