// sphere_sweep: hits against the exact union of spheres (closed forms for linear sweeps, a
// dense search over the spline parameter for the curved ones), grazing rays, rays along the
// sweep, rays from inside, tiny and sign-changing radii, and no NaN from degenerate input.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "render/geometry_test_util.hpp"
#include "render/shapes.hpp"

namespace lumen::render {
namespace {

using namespace testing;

scene::SphereSweep sweep(scene::SweepSpline kind, std::vector<scene::Sphere> spheres) {
    scene::SphereSweep s;
    s.spline = kind;
    s.spheres = std::move(spheres);
    return s;
}

// min over s of |p - c(s)| - |r(s)| of the sweep, by a search over `steps` samples per
// segment, each refined by golden sections when `refine` (independent of the shape's
// polynomials; the coarse form is within a small margin of the exact value).
double sweep_distance(const scene::SphereSweep& s, const glm::dvec3& p, int steps = 400,
                      bool refine = true) {
    double best = 1e300;
    for (const SweepSegment& seg : sweep_segments(s)) {
        auto f = [&](double u) {
            glm::dvec3 c = seg.c[seg.degree];
            double r = seg.r[seg.degree];
            for (int i = seg.degree - 1; i >= 0; --i) c = c * u + seg.c[i], r = r * u + seg.r[i];
            return glm::length(p - c) - std::abs(r);
        };
        for (int i = 0; i <= steps; ++i) best = std::min(best, f(double(i) / steps));
        if (!refine) continue;
        for (int i = 0; i < steps; ++i) {
            double a = double(i) / steps, b = double(i + 1) / steps;
            for (int k = 0; k < 60; ++k) {
                const double m1 = b - 0.618 * (b - a), m2 = a + 0.618 * (b - a);
                (f(m1) < f(m2) ? b : a) = f(m1) < f(m2) ? m2 : m1;
            }
            best = std::min(best, f(0.5 * (a + b)));
        }
    }
    return best;
}

TEST(SphereSweep, LinearCapsuleAndConeAreExact) {
    // Equal radii: a capsule along x; a ray down through the middle meets its side.
    Geometry g(scene_of({make(sweep(scene::SweepSpline::Linear, {{{-1, 0, 0}, 0.5}, {{1, 0, 0}, 0.5}}))}));
    auto h = trace(g, ray({0.3, 5, 0}, {0, -1, 0}));
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->point.y, 0.5, 1e-12);
    EXPECT_NEAR(h->normal.y, 1, 1e-12);
    // Along the axis: the end cap's pole, from either side, and out again from inside.
    auto along = trace(g, ray({-5, 0, 0}, {1, 0, 0}));
    ASSERT_TRUE(along);
    EXPECT_NEAR(along->point.x, -1.5, 1e-12);
    EXPECT_NEAR(along->normal.x, -1, 1e-12);
    auto out = trace(g, ray({0.2, 0, 0}, {1, 0, 0}));
    ASSERT_TRUE(out);
    EXPECT_NEAR(out->point.x, 1.5, 1e-12);
    EXPECT_GT(out->normal.x, 0.99);
    // A tapering cone (radius 1 to 0.5 over 4 units): tangent to both spheres, its slant
    // at sin(a) = 0.5 / 4 from the axis; the side is met at the tangent circle's radius.
    Geometry cone(scene_of({make(sweep(scene::SweepSpline::Linear, {{{0, 0, 0}, 1}, {{4, 0, 0}, 0.5}}))}));
    const double sa = 0.125, ca = std::sqrt(1 - sa * sa);
    // The tangent point on the first sphere is at x = r0 sa, height r0 ca; the side's height
    // at x: r0 ca - (x - r0 sa) tan(a).
    const double x = 2, side = ca - (x - sa) * sa / ca;
    auto hc = trace(cone, ray({x, 5, 0}, {0, -1, 0}));
    ASSERT_TRUE(hc);
    EXPECT_NEAR(hc->point.y, side, 1e-12);
    // The ray is square to the axis, where the envelope polynomial has a double root, known
    // only to about the square root of the rounding: the normal to 1e-7, not 1e-12.
    EXPECT_NEAR(hc->normal.x, sa, 1e-7);
}

TEST(SphereSweep, ASphereHoldingItsNeighbourIsThatSphere) {
    Geometry g(scene_of({make(sweep(scene::SweepSpline::Linear, {{{0, 0, 0}, 0.3}, {{1, 0, 0}, 1.5}}))}));
    for (double y : {0.0, 0.7, 1.4}) {
        auto h = trace(g, ray({1, y, -5}, {0, 0, 1}));
        ASSERT_TRUE(h) << y;
        EXPECT_NEAR(h->point.z, -std::sqrt(1.5 * 1.5 - y * y), 1e-12) << y;
    }
    EXPECT_FALSE(trace(g, ray({1, 1.5 + 1e-9, -5}, {0, 0, 1})));
}

TEST(SphereSweep, SplineHitsLieOnTheEnvelopeAndNoEarlierCrossing) {
    const scene::SphereSweep shapes[] = {
        sweep(scene::SweepSpline::BSpline, {{{-2, 0, 0}, 0.3}, {{-1, 1, 0.5}, 0.6}, {{0, -1, 0}, 0.2},
                                             {{1, 1, -0.5}, 0.5}, {{2, 0, 0}, 0.3}}),
        sweep(scene::SweepSpline::Cubic, {{{-2, 0, 0}, 0.3}, {{-1, 1, 0.5}, 0.4}, {{0, -1, 0}, -0.3},
                                           {{1, 1, -0.5}, 0.5}, {{2, 0, 0}, 0.3}}),
    };
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    for (const scene::SphereSweep& s : shapes) {
        Geometry g(scene_of({make(s)}));
        int hits = 0;
        for (int i = 0; i < 300; ++i) {
            const glm::dvec3 o = 6.0 * glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)));
            const glm::dvec3 aim(1.6 * u(rng), 1.2 * u(rng), 0.6 * u(rng));
            const Ray r = ray(o, aim - o);
            auto h = trace(g, r);
            if (!h) {
                // A miss: the ray stays out of every sphere (coarse march, small margin).
                for (double t = 0; t < 12; t += 0.02)
                    ASSERT_GT(sweep_distance(s, r.at(t), 100, false), -1e-3);
                continue;
            }
            ++hits;
            ASSERT_TRUE(std::isfinite(h->t) && std::isfinite(h->normal.x));
            EXPECT_NEAR(sweep_distance(s, h->point), 0, 1e-7);
            for (double t = 0; t < h->t - 0.05; t += 0.05)
                ASSERT_GT(sweep_distance(s, r.at(t), 100, false), 0);
            // The normal points out: a step along it leaves the sweep.
            EXPECT_GT(sweep_distance(s, h->point + 1e-4 * h->normal, 100), 0);
        }
        EXPECT_GT(hits, 60);
    }
}

TEST(SphereSweep, GrazingTinyAndDegenerateGiveNoNaN) {
    // A radius of 1e-6 (a thread), a sweep of one repeated sphere, a zero radius at an end.
    Geometry g(scene_of({
        make(sweep(scene::SweepSpline::Linear, {{{-1, 0, 0}, 1e-6}, {{1, 0, 0}, 1e-6}})),
        make(sweep(scene::SweepSpline::BSpline, {{{0, 3, 0}, 0.5}, {{0, 3, 0}, 0.5}, {{0, 3, 0}, 0.5}, {{0, 3, 0}, 0.5}})),
        make(sweep(scene::SweepSpline::Linear, {{{3, 0, 0}, 0.5}, {{5, 0, 0}, 0}})),
    }));
    auto thread = trace(g, ray({0, 0, -5}, {0, 0, 1}));
    ASSERT_TRUE(thread);
    EXPECT_NEAR(thread->point.z, -1e-6, 1e-12);
    auto ball = trace(g, ray({0, 3.2, -5}, {0, 0, 1}));
    ASSERT_TRUE(ball);
    EXPECT_NEAR(ball->point.z, -std::sqrt(0.25 - 0.04), 1e-9);
    // Grazing the cone's tip and the ball's rim: a hit or a miss, never a NaN.
    for (double e : {-1e-12, 0.0, 1e-12}) {
        auto tip = trace(g, ray({5 + e, 0, -5}, {0, 0, 1}));
        if (tip) {
            EXPECT_TRUE(std::isfinite(tip->t) && std::isfinite(glm::length(tip->normal)));
        }
        auto rim = trace(g, ray({0.5 + e, 3, -5}, {0, 0, 1}));
        if (rim) {
            EXPECT_TRUE(std::isfinite(rim->t) && std::isfinite(glm::length(rim->normal)));
        }
    }
    // Straight down the cone's axis into its tip.
    auto axis = trace(g, ray({8, 0, 0}, {-1, 0, 0}));
    ASSERT_TRUE(axis);
    EXPECT_NEAR(axis->point.x, 5, 1e-9);
    EXPECT_TRUE(std::isfinite(glm::length(axis->normal)));
}

TEST(SphereSweep, NegativeRadiiAndInsideTest) {
    // All radii negative: POV-Ray's box is inverted and it draws nothing.
    Geometry none(scene_of({make(sweep(scene::SweepSpline::Linear, {{{0, 0, 0}, -1}, {{1, 0, 0}, -1}}))}));
    EXPECT_FALSE(trace(none, ray({0.5, 0, -5}, {0, 0, 1})));
    // One negative radius: its magnitude counts (the radius passes through 0 on the way).
    const scene::SphereSweep pinch =
        sweep(scene::SweepSpline::Linear, {{{0, 0, 0}, 0.5}, {{2, 0, 0}, -0.5}});
    Geometry g(scene_of({make(pinch)}));
    auto h = trace(g, ray({2, 5, 0}, {0, -1, 0}));
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->point.y, 0.5, 1e-9);
    EXPECT_FALSE(trace(g, ray({1, 5, 0.01}, {0, -1, 0})));  // the waist is a point
    SphereSweepShape prepared = make_sphere_sweep(pinch);
    EXPECT_TRUE(inside(prepared, {0.1, 0.2, 0}));
    EXPECT_TRUE(inside(prepared, {1.9, -0.2, 0.1}));
    EXPECT_FALSE(inside(prepared, {1, 0.05, 0}));
    EXPECT_FALSE(inside(prepared, {0, 0.6, 0}));
}

TEST(SphereSweep, ManySegmentsGoThroughTheTree) {
    // A 200-sphere helix: every segment in the tree; hits from outside and from inside agree
    // with a sweep of the same spheres traced piece by piece.
    std::vector<scene::Sphere> helix;
    for (int i = 0; i < 200; ++i) {
        const double a = 0.3 * i;
        helix.push_back({{std::cos(a), 0.02 * i, std::sin(a)}, 0.15});
    }
    const scene::SphereSweep s = sweep(scene::SweepSpline::BSpline, helix);
    Geometry g(scene_of({make(s)}));
    int hits = 0;
    for (int i = 0; i < 40; ++i) {
        const Ray r = ray({5, 0.1 * i, -3}, {-1, 0.01, 0.6});
        auto h = trace(g, r);
        if (!h) continue;
        ++hits;
        EXPECT_NEAR(sweep_distance(s, h->point, 100), 0, 1e-7);
    }
    EXPECT_GT(hits, 10);
}

}  // namespace
}  // namespace lumen::render
