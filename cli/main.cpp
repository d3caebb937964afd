// lumen: renders POV-Ray 3.7 scene files. See cli/run.hpp.
#include "base/heap_pages.hpp"
#include "cli/run.hpp"

int main(int argc, char** argv) {
    lumen::grow_heaps_for_huge_pages();
    return lumen::cli::run_command_line(std::vector<std::string>(argv + 1, argv + argc),
                                        /*process_ends=*/true);
}
