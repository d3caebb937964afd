// `lumen farm`'s plan: a still cut into tiles (+SR/+ER/+SC/+EC) or an animation cut into frame
// ranges (+SF/+EF), each part a lumen run of its own, then a step that joins the tiles (or
// checks the frames); with radiosity, a first run solves each frame's patch solution once into
// a store that every part loads (the solution is view-independent). The plan is plain data:
// cli/farm_run.hpp runs it locally or as Slurm jobs.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "cli/options.hpp"

namespace lumen::cli {

struct FarmSettings {
    int parts = 16;           // tiles of a still, or frame ranges of an animation (at most)
    std::string work;         // folder for parts, logs and the radiosity store
    bool radiosity = false;   // the scene has radiosity: solve it first
    int threads = 0;          // Work_Threads of each run; 0: lumen's default (all cores)
};

struct FarmRun {
    std::string label;              // "tile 3: rows 1-540, columns 961-1920"
    std::vector<std::string> args;  // lumen's arguments (the user's, then the part's own)
    std::vector<std::string> outputs;  // the files it writes
};

struct FarmPlan {
    std::optional<FarmRun> solve;  // the radiosity solve, before every part
    std::vector<FarmRun> parts;
    // A still: the tiles, joined into `output` at the end. An animation: the frames (the parts
    // write them in place), checked at the end.
    std::vector<std::string> tiles;
    std::vector<std::pair<int, int>> tile_origins;  // each tile's top-left pixel (Output_Crop)
    int width = 0, height = 0;                      // the still's size
    std::string output;
    std::vector<std::string> frames;
    std::string work;
};

// The tile grid for `parts` tiles of a width x height image: rows x columns == parts, tiles as
// near square as the factors allow, each at least one render block (`block` pixels) each way.
// Throws LumenError when the image has too few blocks.
struct TileGrid {
    int rows = 1, columns = 1;
};
TileGrid tile_grid(int parts, int width, int height, int block);

// Where tile boundary i of n falls on an axis of `size` pixels: on the render's block grid
// (render/render.hpp: anti-aliasing then gives a tile's pixels their values in the whole image).
int tile_edge(int i, int n, int size, int block);

// The tiles' join: `lumen merge`'s arguments after "merge" (the output, its size, and each
// tile with its position).
std::vector<std::string> merge_arguments(const FarmPlan& plan);

// The plan for lumen's arguments `args` (already parsed into `o`). Throws LumenError where the
// arguments cannot be farmed (no output file, a partial render already, ...).
FarmPlan plan_farm(const std::vector<std::string>& args, const Options& o, const FarmSettings& s);

}  // namespace lumen::cli
