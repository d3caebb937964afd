// Tilings 4, 6-9 and 11-24 against values read from povray 3.7's 16-bit renders (a 1 × 1
// orthographic view of the plane y = 0 at each point, color_map [0 rgb 0] [1 rgb 1]): four
// points a tiling, in different tiles, so a tile moved or of the wrong kind fails.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "render/patterns/tiling_layouts.hpp"
#include "render/patterns/tilings.hpp"

namespace lumen::render {
namespace {

namespace pattern = scene::pattern;

struct Read {
    int tiling;
    int counts[4];  // POV's output at the four points, of 65535
};
const glm::dvec3 kPoints[4] = {{0.3, 0, 0.2}, {1.7, 0, -2.45}, {-3.1, 0, 4.05}, {5.55, 0, 1.35}};
const Read kReads[] = {
    {4, {41349, 50526, 23139, 35465}},  {6, {52428, 45875, 62258, 42598}},
    {7, {32768, 33233, 54279, 29121}},  {8, {50400, 12856, 57968, 5597}},
    {9, {50400, 58031, 43690, 28655}},  {11, {56797, 24030, 63351, 50244}},
    {12, {56797, 30583, 61166, 45875}}, {13, {39321, 23382, 48755, 58933}},
    {14, {36700, 27136, 3039, 9146}},   {15, {19661, 45875, 62258, 42598}},
    {16, {20089, 9281, 43690, 43690}},  {17, {20967, 4641, 54613, 54613}},
    {18, {52428, 45875, 62258, 36044}}, {19, {9752, 14341, 28075, 28655}},
    {20, {9752, 58031, 28075, 43690}},  {21, {6768, 43586, 20026, 21239}},
    {22, {43690, 10630, 43690, 43690}}, {23, {52428, 15370, 49909, 15307}},
    {24, {57671, 9222, 56159, 9184}},
};

TEST(TilingLayouts, ValuesReadFromPovray) {
    for (const Read& r : kReads)
        for (int i = 0; i < 4; ++i) {
            pattern::Tiling t;
            t.type = r.tiling;
            // POV's 16-bit output rounds the value: within half a step of it
            EXPECT_NEAR(evaluate(t, kPoints[i]) * 65535, r.counts[i], 0.5 + 1e-6)
                << "tiling " << r.tiling << " point " << i;
        }
}

// Every kind shows somewhere in a few cells, values stay in [0, 1] and finite far out, and
// the Penrose tilings (render/patterns/penrose.cpp) have no layout.
TEST(TilingLayouts, KindsRangeAndFarPoints) {
    for (int n = 1; n <= 27; ++n) {
        const TilingLayout* layout = tiling_layout(n);
        const bool modelled = n == 4 || (n >= 6 && n <= 9) || (n >= 11 && n <= 24);
        ASSERT_EQ(layout != nullptr, modelled) << "tiling " << n;
        if (!layout) continue;
        pattern::Tiling t;
        t.type = n;
        std::set<int> kinds;
        for (double x = -6; x < 6; x += 0.0731)
            for (double z = -6; z < 6; z += 0.0677) {
                const double v = evaluate(t, {x, 0, z});
                ASSERT_TRUE(v >= 0 && v <= 1) << "tiling " << n << " at " << x << ", " << z;
                kinds.insert(std::min(int(v * layout->kinds), layout->kinds - 1));
            }
        EXPECT_EQ(int(kinds.size()), layout->kinds) << "tiling " << n;
        for (const double far : {1e7, -3.3e9, 1e15}) {
            const double v = evaluate(t, {far, 0, -far / 3});
            EXPECT_TRUE(std::isfinite(v) && v >= 0 && v <= 1) << "tiling " << n;
        }
    }
}

// Either side of a shared edge each tile is at the top of its kind's range.
TEST(TilingLayouts, EdgesAndFlats) {
    pattern::Tiling t;
    t.type = 6;  // the lying brick [1, 3] × [0, 1] (kind 0) meets the standing one [0, 1] × [0, 2]
    EXPECT_NEAR(evaluate(t, {1 - 1e-9, 0, 0.5}), 1, 1e-8);
    EXPECT_NEAR(evaluate(t, {1 + 1e-9, 0, 0.5}), 0.5, 1e-8);
    EXPECT_NEAR(evaluate(t, {2, 0, 0.5}), 0, 1e-12);  // the lying brick's flat middle
    EXPECT_NEAR(evaluate(t, {0.5, 0, 1}), 0.5, 1e-12);  // the standing brick's flat middle
    t.type = 9;  // a hexagon's flat clears the key at 2/3 by POV's 1e-7
    EXPECT_GT(evaluate(t, {0.5, 0, std::sqrt(3.0) / 2}), 2.0 / 3);
}

}  // namespace
}  // namespace lumen::render
