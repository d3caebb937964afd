// What the pavement tests of square, triangular and hexagonal cells share: values read from
// povray's 16-bit renders, checked against an evaluator, and each layout's tiles found by
// joining neighbouring cells of one letter.
#pragma once
#include <gtest/gtest.h>

#include <map>
#include <utility>
#include <vector>

#include "scene/pattern.hpp"
#include "scene/pavement_layouts.hpp"

namespace lumen::render {

struct PavementRead {
    int tiles, number, exterior, interior, form;
    double x, z, value;  // POV's output at (x, 0, z)
};

// Each read against evaluate(layout, settings, x, z), to within POV's 16-bit output.
template <class Reads, class Evaluate>
void expect_pavement_reads(int sides, const Reads& reads, Evaluate evaluate) {
    for (const PavementRead& r : reads) {
        scene::pattern::Pavement k;
        k.sides = sides;
        k.tiles = r.tiles;
        k.number = r.number;
        k.exterior = r.exterior;
        k.interior = r.interior;
        k.form = r.form;
        const scene::PavementLayout* l = scene::pavement_layout(sides, r.tiles, r.number);
        ASSERT_NE(l, nullptr) << r.tiles << " " << r.number;
        EXPECT_NEAR(evaluate(*l, k, r.x, r.z), r.value, 1e-4)
            << "tiles " << r.tiles << " pattern " << r.number << " exterior " << r.exterior
            << " interior " << r.interior << " form " << r.form << " at " << r.x << ", " << r.z;
    }
}

// The tiles of a layout over a stretch of (3 periods + 12) cells each way: cells of one letter
// joined across the edges that `edges(c, r)` lists. A tile that reaches the stretch's edge is
// cut (its size is not the layout's).
struct PavementTiles {
    int width, height;  // the stretch, in cells
    std::map<std::pair<int, int>, int> tile;  // cell -> its tile's index
    std::vector<int> size;
    std::vector<bool> cut;
};
template <class Edges>
PavementTiles pavement_tiles(const scene::PavementLayout& l, Edges edges) {
    PavementTiles t{3 * l.width + 12, 3 * l.height + 12, {}, {}, {}};
    for (int c = 0; c < t.width; ++c)
        for (int r = 0; r < t.height; ++r) {
            if (t.tile.count({c, r})) continue;
            const int index = int(t.size.size());
            std::vector<std::pair<int, int>> todo{{c, r}};
            t.tile[{c, r}] = index;
            int cells = 0;
            bool cut = false;
            while (!todo.empty()) {
                const auto [a, b] = todo.back();
                todo.pop_back();
                ++cells;
                for (const auto& [d, e] : edges(a, b)) {
                    if (d < 0 || e < 0 || d >= t.width || e >= t.height) {
                        cut = true;
                        continue;
                    }
                    if (l.at(d, e) != l.at(a, b) || t.tile.count({d, e})) continue;
                    t.tile[{d, e}] = index;
                    todo.push_back({d, e});
                }
            }
            t.size.push_back(cells);
            t.cut.push_back(cut);
        }
    return t;
}

// Every tile not cut by the stretch has the layout's number of cells.
inline void expect_tiles_of_size(const PavementTiles& t, int tiles, int number) {
    for (std::size_t i = 0; i < t.size.size(); ++i)
        if (!t.cut[i]) {
            EXPECT_EQ(t.size[i], tiles) << "tiles " << tiles << " pattern " << number;
        }
}

}  // namespace lumen::render
