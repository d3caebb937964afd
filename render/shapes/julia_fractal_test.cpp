// julia_fractal: hits agree with the inside test (the reported point is the first one found
// inside, the bisection's last outside point 1e-7 before it), the march stays bounded, every
// normal is finite, and the settings that draw nothing in POV-Ray draw nothing here.
#include <cmath>
#include <random>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "render/shapes/julia_fractal.hpp"

namespace lumen::render {
namespace {

using scene::JuliaAlgebra;
using scene::JuliaFunction;

scene::JuliaFractal quaternion_set() {
    scene::JuliaFractal j;
    j.c = {-0.083, 0.0, -0.83, -0.025};
    j.max_iteration = 8;
    return j;
}

struct Tally {
    int hits = 0, inside_at_hit = 0, outside_before = 0, bad_normals = 0;
};

// Rays from outside the bounding sphere at random points in it.
Tally cast(const JuliaFractalShape& s, int rays, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    Tally t;
    for (int i = 0; i < rays; ++i) {
        const glm::dvec3 o(u(rng) * 3, u(rng) * 3, -5), target(u(rng), u(rng), u(rng));
        const LocalRay r{o, glm::normalize(target - o) * 1.5};  // |d| != 1: t is world distance
        ShapeHit h;
        if (!intersect(s, r, 1e-7, 1e30, h)) continue;
        ++t.hits;
        t.inside_at_hit += inside(s, r.at(h.t));
        t.outside_before += !inside(s, r.at(h.t - 2e-7 / 1.5));
        const double n2 = glm::dot(h.normal, h.normal);
        t.bad_normals += !(std::isfinite(n2) && n2 > 0);
    }
    return t;
}

TEST(JuliaFractal, HitsAreWhereInsideChanges) {
    const Tally t = cast(make_julia_fractal(quaternion_set()), 400, 11);
    ASSERT_GT(t.hits, 100);
    // The last bisection step brackets the surface; rounding of the recomputed points may
    // flip one in a thousand.
    EXPECT_GE(t.inside_at_hit, t.hits * 99 / 100);
    EXPECT_GE(t.outside_before, t.hits * 99 / 100);
    EXPECT_EQ(t.bad_normals, 0);
}

TEST(JuliaFractal, EveryAlgebraAndFunctionGivesFiniteNormals) {
    for (int f = 0; f <= static_cast<int>(JuliaFunction::Pwr); ++f) {
        scene::JuliaFractal j;
        j.c = {0.3, 0.4, 0.2, 0};
        j.algebra = JuliaAlgebra::Hypercomplex;
        j.function = static_cast<JuliaFunction>(f);
        j.exponent = {2, 0.3};
        j.max_iteration = 6;
        j.slice = {0.1, 0.2, 0, std::sqrt(0.95)};
        SCOPED_TRACE(f);
        const Tally t = cast(make_julia_fractal(j), 60, 5);
        EXPECT_EQ(t.bad_normals, 0);
    }
    scene::JuliaFractal cube = quaternion_set();
    cube.function = JuliaFunction::Cube;
    const Tally t = cast(make_julia_fractal(cube), 200, 3);
    EXPECT_GT(t.hits, 20);
    EXPECT_EQ(t.bad_normals, 0);
}

TEST(JuliaFractal, CsgCrossingsAlternate) {
    // Asking again from each hit walks the crossings: entering and leaving alternate.
    const JuliaFractalShape s = make_julia_fractal(quaternion_set());
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> u(-0.6, 0.6);
    int walked = 0;
    for (int i = 0; i < 100; ++i) {
        const LocalRay r{{u(rng), u(rng), -3}, {0, 0, 1}};
        double from = 1e-7;
        bool in = inside(s, r.o);
        ShapeHit h;
        int n = 0;
        while (n < 50 && intersect(s, r, from, 1e30, h)) {
            ASSERT_GT(h.t, from);
            const bool after = inside(s, r.at(h.t + 1e-6));
            if (after != in) ++walked;
            in = after;
            from = h.t;
            ++n;
        }
        ASSERT_LT(n, 50);
    }
    EXPECT_GT(walked, 20);
}

TEST(JuliaFractal, StandAloneStopsAtANearFirstCrossing) {
    // c = 0 and w = 0.5: the ball of radius sqrt(0.75), clear of the bounding sphere. A shadow
    // ray (tmin 1e-3) from 5e-5 outside it, heading in: its first crossing lies nearer than
    // POV-Ray's 1e-4, so a stand-alone fractal is not hit at all; a CSG child goes on to the
    // crossing beyond (the way out).
    scene::JuliaFractal j;
    j.c = {0, 0, 0, 0};
    j.slice_distance = 0.5;
    j.precision = 100;
    JuliaFractalShape s = make_julia_fractal(j);
    const double r = std::sqrt(0.75);
    const LocalRay ray{{-r - 5e-5, 0, 0}, {1, 0, 0}};
    ShapeHit h;
    EXPECT_FALSE(intersect(s, ray, 1e-3, 1e30, h));
    ASSERT_TRUE(intersect(s, ray, 1e-6, 1e30, h));  // a camera ray sees the entry
    EXPECT_NEAR(h.t, 5e-5, 2e-7);
    s.csg_child = true;
    ASSERT_TRUE(intersect(s, ray, 1e-3, 1e30, h));
    EXPECT_NEAR(h.t, 2 * r + 5e-5, 2e-7);
}

TEST(JuliaFractal, NoIterationsOrOneDrawNothing) {
    // POV-Ray: with max_iteration 0 every point is inside, with 1 the whole bounding sphere
    // is; a ray starting inside never sees the state change.
    for (int n : {0, 1}) {
        scene::JuliaFractal j = quaternion_set();
        j.max_iteration = n;
        EXPECT_EQ(cast(make_julia_fractal(j), 50, 1).hits, 0) << n;
    }
}

TEST(JuliaFractal, BoundsHoldTheSphere) {
    const JuliaFractalShape s = make_julia_fractal(quaternion_set());
    const double r = 1 + std::sqrt(0.083 * 0.083 + 0.83 * 0.83 + 0.025 * 0.025) + 1e-7;
    const Aabb b = bounds(s);
    EXPECT_NEAR(b.hi.x, r, 1e-9);
    EXPECT_NEAR(b.lo.z, -r, 1e-9);
    EXPECT_FALSE(inside(s, {0, 0, r * 1.01}));
}

}  // namespace
}  // namespace lumen::render
