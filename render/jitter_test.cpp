#include "render/jitter.hpp"

#include <gtest/gtest.h>

#include <set>

namespace lumen::render {
namespace {

TEST(Jitter, TableHas256DistinctOffsetsInTheHalfOpenUnit) {
    const std::array<float, 256>& t = jitter_table();
    std::set<float> distinct(t.begin(), t.end());
    EXPECT_EQ(distinct.size(), 256u);
    for (float v : t) {
        EXPECT_GE(v, -0.5f);
        EXPECT_LT(v, 0.5f);
    }
}

// Pixels of POV-Ray's own render of tools/jitter/probe.pov (256x256, 16-bit PPM, +A0.0 +AM1
// +R1 +J1): each reads red = (1 + jx)/2 and green = (1 − jy)/2 of its one jittered sample.
TEST(Jitter, MatchesPixelsOfPovRaysProbeRender) {
    struct Pixel {
        int x, y;
        unsigned red, green;
    };
    const Pixel pov[] = {{0, 0, 35520, 30015},   {1, 0, 39359, 39551},    {0, 1, 32576, 23424},
                         {31, 32, 49023, 30655}, {100, 37, 36287, 17792}, {255, 255, 30017, 41855}};
    const double level = 2.0 / 65535;  // one 16-bit level of a reading, in pixels
    for (const Pixel& p : pov) {
        double jx, jy;
        jitter2d(p.x, p.y, jx, jy);
        EXPECT_NEAR(jx, 2.0 * p.red / 65535 - 1, level) << p.x << "," << p.y;
        EXPECT_NEAR(jy, 1 - 2.0 * p.green / 65535, level) << p.x << "," << p.y;
    }
}

TEST(Jitter, IsAFunctionOfThePositionOnly) {
    double a, b, c, d;
    jitter2d(12.25, -0.75, a, b);
    jitter2d(3, 4, c, d);
    jitter2d(12.25, -0.75, c, d);
    EXPECT_EQ(a, c);
    EXPECT_EQ(b, d);
}

}  // namespace
}  // namespace lumen::render
