#include "cli/farm_plan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "base/diagnostics.hpp"
#include "cli/frames.hpp"

namespace lumen::cli {
namespace {

std::string range(int a, int b) { return std::to_string(a) + "-" + std::to_string(b); }

}  // namespace

int tile_edge(int i, int n, int size, int block) {
    if (i >= n) return size;
    const int blocks = (size + block - 1) / block;
    return int((long long)blocks * i / n) * block;
}

TileGrid tile_grid(int parts, int width, int height, int block) {
    TileGrid best{0, 0};
    double best_score = 0;
    const int block_rows = (height + block - 1) / block, block_columns = (width + block - 1) / block;
    for (int rows = 1; rows <= parts; ++rows) {
        if (parts % rows) continue;
        const int columns = parts / rows;
        if (rows > block_rows || columns > block_columns) continue;
        // How far a tile is from square, either way.
        const double aspect = (double(width) / columns) / (double(height) / rows);
        const double score = std::abs(std::log(aspect));
        if (best.rows == 0 || score < best_score) {
            best = {rows, columns};
            best_score = score;
        }
    }
    if (best.rows == 0)
        throw LumenError({}, "cannot cut a " + std::to_string(width) + "x" + std::to_string(height) +
                                 " image into " + std::to_string(parts) + " tiles",
                         "a tile is at least one render block (+BS, " + std::to_string(block) +
                             " pixels here); ask for fewer parts");
    return best;
}

std::vector<std::string> merge_arguments(const FarmPlan& plan) {
    std::vector<std::string> args = {plan.output, "--size=" + std::to_string(plan.width) + "," +
                                                      std::to_string(plan.height)};
    for (size_t i = 0; i < plan.tiles.size(); ++i) {
        args.push_back("--at=" + std::to_string(plan.tile_origins[i].first) + "," +
                       std::to_string(plan.tile_origins[i].second));
        args.push_back(plan.tiles[i]);
    }
    return args;
}

FarmPlan plan_farm(const std::vector<std::string>& args, const Options& o, const FarmSettings& s) {
    const SourceLoc cmd;
    if (!o.output_to_file) throw LumenError(cmd, "lumen farm writes files: leave out -F");
    if (o.start_row || o.end_row || o.start_col || o.end_col)
        throw LumenError(cmd, "lumen farm cuts the whole image into tiles itself",
                         "leave out +SR, +ER, +SC and +EC (Start_Row, ...)");
    if (o.dump_scene || o.check || o.radiosity_only)
        throw LumenError(cmd, "lumen farm renders: leave out --dump-scene, --check and --radiosity-only");
    if (s.parts < 1) throw LumenError(cmd, "lumen farm needs at least one part");

    namespace fs = std::filesystem;
    FarmPlan plan;
    plan.work = s.work;
    const fs::path work(s.work);
    std::vector<std::string> common = args;
    if (s.threads > 0) common.push_back("Work_Threads=" + std::to_string(s.threads));
    if (s.radiosity) {
        const std::string store = "Radiosity_Store=" + (work / "radiosity").string();
        common.push_back(store);
        FarmRun solve{"radiosity solve", common, {}};
        solve.args.push_back("--radiosity-only");
        plan.solve = std::move(solve);
    }

    const std::vector<Frame> frames = plan_frames(o);
    if (is_animation(o)) {
        const int n = int(frames.size());
        const int count = std::min(s.parts, n);
        for (int j = 0; j < count; ++j) {
            const int a = frames[size_t(n * j / count)].number;
            const int b = frames[size_t(n * (j + 1) / count - 1)].number;
            FarmRun run{"frames " + range(a, b), common, {}};
            run.args.push_back("Subset_Start_Frame=" + std::to_string(a));
            run.args.push_back("Subset_End_Frame=" + std::to_string(b));
            for (const Frame& f : frames)
                if (f.number >= a && f.number <= b) run.outputs.push_back(f.output);
            plan.parts.push_back(std::move(run));
        }
        for (const Frame& f : frames) plan.frames.push_back(f.output);
        return plan;
    }

    plan.output = frames.front().output;
    const int w = o.render.width, h = o.render.height;
    plan.width = w;
    plan.height = h;
    const int block = render::effective_block_size(o.render);
    const TileGrid grid = tile_grid(s.parts, w, h, block);
    const std::string ext = extension_for(o.image.type);
    const int digits = int(std::to_string(s.parts - 1).size());
    for (int r = 0; r < grid.rows; ++r) {
        for (int c = 0; c < grid.columns; ++c) {
            const int index = r * grid.columns + c;
            // 1-based pixel indices; an end index is at least a block (POV reads 1 as a fraction).
            const int top = tile_edge(r, grid.rows, h, block) + 1;
            const int bottom = tile_edge(r + 1, grid.rows, h, block);
            const int left = tile_edge(c, grid.columns, w, block) + 1;
            const int right = tile_edge(c + 1, grid.columns, w, block);
            char name[48];
            std::snprintf(name, sizeof name, "part-%0*d", digits, index);
            const std::string file = (work / "parts" / (name + ext)).string();
            FarmRun run{"tile " + std::to_string(index) + ": rows " + range(top, bottom) +
                            ", columns " + range(left, right),
                        common, {file}};
            run.args.push_back("Start_Row=" + std::to_string(top));
            run.args.push_back("End_Row=" + std::to_string(bottom));
            run.args.push_back("Start_Column=" + std::to_string(left));
            run.args.push_back("End_Column=" + std::to_string(right));
            run.args.push_back("Output_File_Name=" + file);
            run.args.push_back("Output_Crop=on");  // only its area: lumen merge places it
            plan.tiles.push_back(file);
            plan.tile_origins.emplace_back(left - 1, top - 1);
            plan.parts.push_back(std::move(run));
        }
    }
    return plan;
}

}  // namespace lumen::cli
