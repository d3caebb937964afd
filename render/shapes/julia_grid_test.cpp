// The julia_fractal emptiness grid: it must never change a result. Rays and points through
// each kind of set give bit-identical hits, normals and inside tests with and without it, and
// it does prove most of the bounding cube empty (else it would cost without helping).
#include <cmath>
#include <random>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "render/shapes/julia_fractal.hpp"

namespace lumen::render {
namespace {

using scene::JuliaAlgebra;
using scene::JuliaFunction;

scene::JuliaFractal make_set(JuliaAlgebra algebra, JuliaFunction function, glm::dvec4 c,
                             int iterations) {
    scene::JuliaFractal j;
    j.algebra = algebra;
    j.function = function;
    j.c = {c.x, c.y, c.z, c.w};
    j.max_iteration = iterations;
    j.precision = 40;
    return j;
}

std::vector<scene::JuliaFractal> sets() {
    std::vector<scene::JuliaFractal> v = {
        make_set(JuliaAlgebra::Quaternion, JuliaFunction::Sqr, {-0.083, 0, -0.83, -0.025}, 8),
        make_set(JuliaAlgebra::Quaternion, JuliaFunction::Sqr, {-0.03, 0.5, -0.2, -0.5}, 12),
        make_set(JuliaAlgebra::Quaternion, JuliaFunction::Cube, {-0.033, -0.6, -0.93, -0.025}, 6),
        make_set(JuliaAlgebra::Hypercomplex, JuliaFunction::Sqr, {0.2, 0.1, 0.59, -0.2}, 7),
        make_set(JuliaAlgebra::Hypercomplex, JuliaFunction::Cube, {-0.2, 0.4, 0.1, 0.3}, 5),
    };
    v.back().slice = {0.2, 0.1, 0.3, 0.9};  // a tilted slice: w varies across a cell
    v.back().slice_distance = 0.1;
    return v;
}

TEST(JuliaGrid, NeverChangesAHitOrAnInsideTest) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    for (const scene::JuliaFractal& j : sets()) {
        const JuliaFractalShape with = make_julia_fractal(j);
        ASSERT_TRUE(with.grid);
        JuliaFractalShape without = with;
        without.grid = nullptr;
        int hits = 0;
        for (int i = 0; i < 3000; ++i) {
            // Rays from outside and from inside the sphere (shadow-like starts), any length.
            const glm::dvec3 o = i % 3 ? glm::dvec3(u(rng) * 3, u(rng) * 3, -4)
                                       : glm::dvec3(u(rng), u(rng), u(rng)) * 1.2;
            const glm::dvec3 target(u(rng) * 1.3, u(rng) * 1.3, u(rng) * 1.3);
            const LocalRay r{o, (target - o) * (0.5 + 0.5 * (u(rng) + 1))};
            ShapeHit a, b;
            const bool ha = intersect(with, r, 1e-6, 1e30, a);
            const bool hb = intersect(without, r, 1e-6, 1e30, b);
            ASSERT_EQ(ha, hb) << "ray " << i;
            if (ha) {
                ++hits;
                EXPECT_EQ(a.t, b.t);
                EXPECT_EQ(a.normal, b.normal);
            }
            const glm::dvec3 p = target * 1.2;
            ASSERT_EQ(inside(with, p), inside(without, p)) << "point " << i;
        }
        EXPECT_GT(hits, 100);
        EXPECT_LT(with.grid->occupied_fraction(), 0.5);
    }
}

TEST(JuliaGrid, NotBuiltWhereNoEnclosureIsKnown) {
    EXPECT_FALSE(make_julia_fractal(
                     make_set(JuliaAlgebra::Hypercomplex, JuliaFunction::Exp, {0.1, 0.2, 0, 0}, 6))
                     .grid);
}

TEST(JuliaGrid, SegmentsOutsideOrDegenerateAreSafe) {
    const JuliaFractalShape s = make_julia_fractal(sets()[0]);
    // A segment wholly outside the cube meets no cell; a point-like one inside its cell.
    EXPECT_FALSE(s.grid->segment_may_hit({5, 5, 5}, {6, 6, 6}));
    EXPECT_EQ(s.grid->segment_may_hit({0, 0, 0}, {0, 0, 0}), s.grid->may_contain({0, 0, 0}));
    // A non-finite end leaves the decision to the march.
    EXPECT_TRUE(s.grid->segment_may_hit({std::nan(""), 0, 0}, {1, 0, 0}));
    EXPECT_TRUE(s.grid->segment_may_hit({0, 0, 0}, {HUGE_VAL, 0, 0}));
}

}  // namespace
}  // namespace lumen::render
