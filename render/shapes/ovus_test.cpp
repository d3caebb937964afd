// ovus: its profile against POV-Ray's (traced with povray's trace()), the degenerate lemon,
// rays along the axis, and rays from inside.
#include <cmath>

#include <gtest/gtest.h>

#include "render/geometry_test_util.hpp"
#include "render/shapes.hpp"

namespace lumen::render {
namespace {

using namespace testing;

// povray: trace(ovus { 1, 0.6 }, <5, y, 0>, <-1, 0, 0>, N) for some y: the hit x and N.
struct Probe {
    double y, x, nx, ny;
};
constexpr Probe kOvus1_06[] = {
    {-0.9, 0.435889894, 0.435889894, -0.9},   // bottom sphere
    {-0.1, 0.994987437, 0.994987437, -0.1},
    {0.0, 1.000100018, 0.999949999, -0.01},   // the lemon
    {0.5, 0.941745796, 0.970772888, 0.24},
    {1.4, 0.447818754, 0.723809367, 0.69},
    {1.5, 0.331662479, 0.552770798, 0.833333333},  // top sphere
};

TEST(Ovus, ProfileMatchesPovRay) {
    Geometry g(scene_of({make(scene::Ovus{1, 0.6})}));
    for (const Probe& p : kOvus1_06) {
        auto h = trace(g, ray({5, p.y, 0}, {-1, 0, 0}));
        ASSERT_TRUE(h) << p.y;
        EXPECT_NEAR(h->point.x, p.x, 1e-8) << p.y;
        EXPECT_NEAR(h->normal.x, p.nx, 1e-8) << p.y;
        EXPECT_NEAR(h->normal.y, p.ny, 1e-8) << p.y;
    }
    EXPECT_FALSE(trace(g, ray({5, 1.6 + 1e-9, 0}, {-1, 0, 0})));
    EXPECT_FALSE(trace(g, ray({5, -1 - 1e-9, 0}, {-1, 0, 0})));
}

TEST(Ovus, AlongTheAxisAndFromInside) {
    Geometry g(scene_of({make(scene::Ovus{0.5, 0.9})}));
    auto down = trace(g, ray({0, 5, 0}, {0, -1, 0}));
    ASSERT_TRUE(down);
    EXPECT_NEAR(down->point.y, 0.5 + 0.9, 1e-12);
    auto up = trace(g, ray({0, -5, 0}, {0, 1, 0}));
    ASSERT_TRUE(up);
    EXPECT_NEAR(up->point.y, -0.5, 1e-12);  // the bottom sphere's pole, below the lemon
    auto out = trace(g, ray({0, 0.2, 0}, {1, 0, 0}));
    ASSERT_TRUE(out);
    EXPECT_GT(out->normal.x, 0);
    EXPECT_FALSE(trace(g, ray(out->point + 1e-6 * glm::dvec3(1, 0, 0), {1, 0, 0})));
}

TEST(Ovus, DegenerateRadiiAreNeverHitOrFinite) {
    // A zero top radius leaves the bottom sphere; no NaN from the vanished lemon.
    Geometry g(scene_of({make(scene::Ovus{1, 0})}));
    auto h = trace(g, ray({3, 0.3, -4}, {-3, 0, 4}));
    ASSERT_TRUE(h);
    EXPECT_NEAR(glm::length(h->point), 1, 1e-9);
    Geometry bad(scene_of({make(scene::Ovus{-1, 0.5}), make(scene::Ovus{std::nan(""), 1})}));
    EXPECT_FALSE(trace(bad, ray({0, 0, -5}, {0, 0, 1})));
}

}  // namespace
}  // namespace lumen::render
