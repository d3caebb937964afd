// lumen farm's plan: tiles that cover the image exactly once, frame ranges that cover the
// animation exactly once, the radiosity solve before every part, and what cannot be farmed.
#include <gtest/gtest.h>

#include "base/diagnostics.hpp"
#include "cli/command_line.hpp"
#include "cli/farm_plan.hpp"

namespace lumen::cli {
namespace {

Options parse(const std::vector<std::string>& args) {
    SourceManager sources;
    return parse_command_line(args, sources);
}

FarmPlan plan(const std::vector<std::string>& args, int parts, bool radiosity = false) {
    FarmSettings s;
    s.parts = parts;
    s.work = "w.farm";
    s.radiosity = radiosity;
    return plan_farm(args, parse(args), s);
}

TEST(FarmPlan, TileGridIsNearSquareOnTheBlockGrid) {
    EXPECT_EQ(tile_grid(16, 3840, 2160, 32).rows, 4);
    EXPECT_EQ(tile_grid(16, 3840, 2160, 32).columns, 4);
    EXPECT_EQ(tile_grid(6, 640, 480, 32).rows, 2);
    EXPECT_EQ(tile_grid(6, 640, 480, 32).columns, 3);
    EXPECT_EQ(tile_grid(7, 640, 480, 32).columns, 7);  // a prime: one row of columns
    EXPECT_EQ(tile_grid(1, 5, 5, 5).rows, 1);
    EXPECT_EQ(tile_grid(4, 20, 400, 32).rows, 4);  // one block wide
    EXPECT_THROW(tile_grid(3, 64, 64, 32), LumenError);  // 2 x 2 blocks: no 3 x 1 or 1 x 3
    EXPECT_EQ(tile_grid(3, 65, 64, 32).columns, 3);      // 3 x 2 blocks
    EXPECT_EQ(tile_edge(0, 3, 100, 8), 0);
    EXPECT_EQ(tile_edge(1, 3, 100, 8), 32);  // 13 blocks: 4, 4, 5
    EXPECT_EQ(tile_edge(2, 3, 100, 8), 64);
    EXPECT_EQ(tile_edge(3, 3, 100, 8), 100);
}

// Every pixel in exactly one tile, through the options each part's lumen would read, and
// every tile edge on the render's block grid.
TEST(FarmPlan, TilesCoverTheImageOnceOnBlockEdges) {
    for (const auto& [size, parts] : {std::pair<std::vector<std::string>, int>{{"+W97", "+H61", "+BS8"}, 6},
                                      {{"+W3840", "+H2160"}, 16},
                                      {{"+W100", "+H10", "+BS4"}, 5},
                                      {{"+W64", "+H48"}, 2}}) {
        std::vector<std::string> args = {"s.pov"};
        args.insert(args.end(), size.begin(), size.end());
        const Options o = parse(args);
        const int w = o.render.width, h = o.render.height, block = o.render.block_size;
        const FarmPlan p = plan(args, parts);
        ASSERT_EQ(int(p.parts.size()), parts);
        EXPECT_EQ(p.output, "s.png");
        std::vector<int> covered(size_t(w) * h, 0);
        for (const FarmRun& run : p.parts) {
            const render::RenderOptions r = effective_render_options(parse(run.args));
            EXPECT_EQ(r.width, w);
            EXPECT_EQ(r.start_row % block, 0);
            EXPECT_EQ(r.start_col % block, 0);
            for (int y = r.start_row; y <= r.end_row; ++y)
                for (int x = r.start_col; x <= r.end_col; ++x) ++covered[size_t(y) * w + x];
        }
        for (const int c : covered) ASSERT_EQ(c, 1) << w << "x" << h << " in " << parts;
        EXPECT_EQ(p.tiles.size(), size_t(parts));
        EXPECT_EQ(parse(p.parts[1].args).output, p.tiles[1]);
        // Each tile writes its area alone and the join places it there.
        const Options tile = parse(p.parts.back().args);
        EXPECT_TRUE(tile.crop_output);
        const render::RenderOptions r = effective_render_options(tile);
        const std::vector<std::string> m = merge_arguments(p);
        EXPECT_EQ(m[0], "s.png");
        EXPECT_EQ(m[1], "--size=" + std::to_string(w) + "," + std::to_string(h));
        EXPECT_EQ(m[m.size() - 2], "--at=" + std::to_string(r.start_col) + "," + std::to_string(r.start_row));
        EXPECT_EQ(m.back(), p.tiles.back());
    }
}

TEST(FarmPlan, AnimationFrameRangesCoverEveryFrameOnce) {
    const std::vector<std::string> args = {"a.pov", "+W8", "+H6", "+KFI1", "+KFF30", "+SF3", "+EF29"};
    const FarmPlan p = plan(args, 4);
    ASSERT_EQ(p.parts.size(), 4u);
    EXPECT_TRUE(p.tiles.empty());
    ASSERT_EQ(p.frames.size(), 27u);
    EXPECT_EQ(p.frames.front(), "a03.png");
    std::vector<int> seen(31, 0);
    for (const FarmRun& run : p.parts) {
        const Options o = parse(run.args);
        for (int f = *o.subset_start; f <= *o.subset_end; ++f) ++seen[size_t(f)];
        EXPECT_EQ(run.outputs.size(), size_t(*o.subset_end - *o.subset_start + 1));
    }
    for (int f = 0; f <= 30; ++f) EXPECT_EQ(seen[size_t(f)], f >= 3 && f <= 29 ? 1 : 0) << f;
    // More parts than frames: one frame each.
    EXPECT_EQ(plan({"a.pov", "+KFI1", "+KFF4"}, 16).parts.size(), 4u);
}

TEST(FarmPlan, RadiosityIsSolvedOnceIntoAStoreEveryPartReads) {
    const FarmPlan p = plan({"r.pov", "+W64", "+H48"}, 4, true);
    ASSERT_TRUE(p.solve.has_value());
    EXPECT_TRUE(parse(p.solve->args).radiosity_only);
    const std::string store = parse(p.solve->args).radiosity.store;
    EXPECT_EQ(store, "w.farm/radiosity");
    for (const FarmRun& run : p.parts) {
        EXPECT_EQ(parse(run.args).radiosity.store, store);
        EXPECT_FALSE(parse(run.args).radiosity_only);
    }
    EXPECT_FALSE(plan({"r.pov", "+W64", "+H48"}, 4).solve.has_value());
}

TEST(FarmPlan, RefusesWhatItCannotFarm) {
    EXPECT_THROW(plan({"s.pov", "+W64", "+H48", "-F"}, 4), LumenError);
    EXPECT_THROW(plan({"s.pov", "+W64", "+H48", "+SR0.5"}, 4), LumenError);
    EXPECT_THROW(plan({"s.pov", "+W64", "+H48", "--check"}, 4), LumenError);
    EXPECT_THROW(plan({"s.pov", "+W40", "+H30"}, 4), LumenError);  // one 32-pixel block
}

TEST(FarmPlan, ThreadsGoToEveryRun) {
    FarmSettings s;
    s.parts = 2;
    s.work = "w";
    s.threads = 3;
    const std::vector<std::string> args = {"s.pov", "+W64", "+H48"};
    for (const FarmRun& run : plan_farm(args, parse(args), s).parts)
        EXPECT_EQ(parse(run.args).render.threads, 3);
}

}  // namespace
}  // namespace lumen::cli
