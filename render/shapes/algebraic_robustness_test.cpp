// poly, quadric and superellipsoid: agreement with closed shapes, rays starting on the
// surface, tangent and grazing rays, exponents near 0 and 1, far objects, bad input.
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "render/geometry_test_util.hpp"
#include "render/shapes.hpp"

namespace lumen::render {
namespace {

using namespace testing;

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// (x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + z^2) as a quartic.
scene::Poly torus_quartic(double R, double r, bool sturm) {
    scene::Poly p;
    p.order = 4;
    p.sturm = sturm;
    p.coeffs.assign(scene::Poly::term_count(4), 0);
    auto set = [&](int i, int j, int k, double c) { p.coeffs[scene::Poly::term_index(4, i, j, k)] = c; };
    const double a = R * R - r * r, b = 4 * R * R;
    set(4, 0, 0, 1); set(0, 4, 0, 1); set(0, 0, 4, 1);
    set(2, 2, 0, 2); set(2, 0, 2, 2); set(0, 2, 2, 2);
    set(2, 0, 0, 2 * a - b); set(0, 2, 0, 2 * a); set(0, 0, 2, 2 * a - b);
    set(0, 0, 0, a * a);
    return p;
}

TEST(Poly, QuarticTorusMatchesTheTorusShape) {
    const double R = 1, r = 0.4;
    for (bool sturm : {false, true}) {
        SCOPED_TRACE(sturm);
        Geometry quartic(scene_of({make(torus_quartic(R, r, sturm))}));
        Geometry torus(scene_of({make(scene::Torus{R, r, false})}));
        std::mt19937 rng(5);
        std::uniform_real_distribution<double> u(-1, 1);
        int hits = 0;
        for (int i = 0; i < 300; ++i) {
            glm::dvec3 o{u(rng) * 4, u(rng) * 4, -4}, target{u(rng) * 1.4, u(rng) * 0.4, u(rng)};
            Ray rr = ray(o, target - o);
            auto a = trace(quartic, rr), b = trace(torus, rr);
            ASSERT_EQ(bool(a), bool(b)) << i;
            if (!a) continue;
            ++hits;
            EXPECT_NEAR(a->t, b->t, 1e-6) << i;
            EXPECT_NEAR(glm::dot(a->normal, b->normal), 1, 1e-6) << i;
        }
        EXPECT_GT(hits, 100);
    }
}

TEST(Poly, RayLeavingTheSurfaceDoesNotHitItsOrigin) {
    // The 1e-4 root elimination and depth: a secondary ray from a hit point goes on to the
    // far side of the tube, never back to t ~ 0.
    Geometry g(scene_of({make(torus_quartic(1, 0.4, false))}));
    auto h = trace(g, ray({-5, 0, 0}, {1, 0, 0}));
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 3.6, 1e-9);
    auto next = trace(g, ray(h->point, {1, 0, 0}), false, 0);
    ASSERT_TRUE(next);
    EXPECT_NEAR(next->t, 0.8, 1e-9);
}

TEST(Poly, UnboundedInsideWithPovToleranceAndBadInput) {
    auto torus = make(torus_quartic(1, 0.4, false));
    EXPECT_TRUE(Geometry::inside(*torus, {1, 0, 0}));
    EXPECT_FALSE(Geometry::inside(*torus, {0, 0, 0}));
    // A plane-like order-2 poly z = 0 far away is still found (no bounds).
    scene::Poly plane;
    plane.order = 2;
    plane.coeffs.assign(10, 0);
    plane.coeffs[scene::Poly::term_index(2, 0, 0, 1)] = 1;
    plane.coeffs[9] = -1e5;
    Geometry far(scene_of({make(plane)}));
    auto h = trace(far, ray({0.3, 0.2, 0}, {0, 0, 1}));
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 1e5, 1e-6);
    // NaN coefficients or a wrong count: never hit, never NaN.
    scene::Poly bad = torus_quartic(1, 0.4, false);
    bad.coeffs[3] = std::numeric_limits<double>::quiet_NaN();
    Geometry gb(scene_of({make(bad)}));
    EXPECT_FALSE(trace(gb, ray({-5, 0, 0}, {1, 0, 0})));
    bad.coeffs.pop_back();
    Geometry gc(scene_of({make(bad)}));
    EXPECT_FALSE(trace(gc, ray({-5, 0, 0}, {1, 0, 0})));
}

TEST(Quadric, TangentRaysMissAndLinearCaseHits) {
    // x^2 + y^2 + z^2 - 1: POV-Ray's discriminant <= 0 misses a tangent ray.
    Geometry sphere(scene_of({make(scene::Quadric{{1, 1, 1}, {0, 0, 0}, {0, 0, 0}, -1})}));
    EXPECT_FALSE(trace(sphere, ray({-5, 1, 0}, {1, 0, 0})));
    auto h = trace(sphere, ray({-5, 1 - 1e-6, 0}, {1, 0, 0}));
    ASSERT_TRUE(h);
    EXPECT_TRUE(finite(h->normal));
    // Paraboloid x^2 + z^2 - y: a ray along y has no quadratic term, one root.
    Geometry para(scene_of({make(scene::Quadric{{1, 0, 1}, {0, 0, 0}, {0, -1, 0}, 0})}));
    auto p = trace(para, ray({0.5, -3, 0}, {0, 1, 0}));
    ASSERT_TRUE(p);
    EXPECT_NEAR(p->t, 3.25, 1e-12);
    EXPECT_FALSE(trace(para, ray({0.5, 3, 0}, {0, 1, 0})));
    // Scaled far away, the folded coefficients keep the hit precise.
    Geometry far(scene_of({make(scene::Quadric{{1, 1, 1}, {0, 0, 0}, {0, 0, 0}, -1},
                                scale({2, 2, 2}).then(translate({0, 0, 1e5})))}));
    auto f = trace(far, ray({0, 0, 0}, {0, 0, 1}));
    ASSERT_TRUE(f);
    EXPECT_NEAR(f->t, 1e5 - 2, 1e-5);
}

// Two shapes around the origin met by the same random rays: same hits, same normals; returns
// how many rays hit.
int expect_same_hits(const Geometry& a, const Geometry& b, unsigned seed, int rays,
                     double tolerance) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    int hits = 0;
    for (int i = 0; i < rays; ++i) {
        glm::dvec3 o{u(rng) * 3, u(rng) * 3, -3}, target{u(rng), u(rng), u(rng)};
        Ray rr = ray(o, target - o);
        auto ha = trace(a, rr), hb = trace(b, rr);
        EXPECT_EQ(bool(ha), bool(hb)) << i;
        if (!ha || !hb) continue;
        ++hits;
        EXPECT_NEAR(ha->t, hb->t, tolerance) << i;
        EXPECT_NEAR(glm::dot(glm::normalize(ha->normal), glm::normalize(hb->normal)), 1,
                    tolerance)
            << i;
    }
    return hits;
}

TEST(Superellipsoid, OneOneIsTheUnitSphere) {
    Geometry se(scene_of({make(scene::Superellipsoid{1, 1})}));
    Geometry sphere(scene_of({make(scene::Sphere{{0, 0, 0}, 1})}));
    EXPECT_GT(expect_same_hits(se, sphere, 9, 200, 1e-8), 20);
}

TEST(Superellipsoid, ExponentsNearZeroAndGrazingRays) {
    for (double en : {0.01, 0.001, 1e-6}) {
        SCOPED_TRACE(en);
        Geometry box(scene_of({make(scene::Superellipsoid{en, en})}));
        auto h = trace(box, ray({0.5, 0.3, -5}, {0, 0, 1}));
        ASSERT_TRUE(h);
        EXPECT_NEAR(h->t, 4, 1e-2);
        EXPECT_NEAR(h->normal.z, -1, 1e-6);
        // Along a face: just inside, on it and just outside: finite answers only.
        for (double y : {1 - 1e-9, 1.0, 1 + 1e-9}) {
            Hit hit;
            if (box.intersect(ray({-5, y, 0.2}, {1, 0, 0}), 1e-4, 1e30, hit)) {
                EXPECT_TRUE(std::isfinite(hit.t));
                EXPECT_TRUE(finite(hit.normal));
            }
        }
        EXPECT_FALSE(trace(box, ray({-5, 1.02, 0.2}, {1, 0, 0})));
    }
}

TEST(Superellipsoid, LargeIntegerPowersTraceAsTheRealOnesBesideThem) {
    // 2/e = 40 is computed by squaring, 2/e a hair from 40 by pow: the same surface.
    Geometry squared(scene_of({make(scene::Superellipsoid{0.05, 0.05})}));
    Geometry real(scene_of({make(scene::Superellipsoid{0.05 * (1 + 1e-13), 0.05 * (1 + 1e-13)})}));
    EXPECT_GT(expect_same_hits(squared, real, 21, 300, 1e-9), 100);
}

TEST(Superellipsoid, NZeroAndFarAway) {
    // n = 0: 2/n is infinite, the z profile a square (POV-Ray keeps the infinities).
    Geometry cyl(scene_of({make(scene::Superellipsoid{1, 0})}));
    auto h = trace(cyl, ray({0, 0.2, -5}, {0, 0, 1}));
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 4, 1e-6);
    EXPECT_TRUE(finite(h->normal));
    auto side = trace(cyl, ray({-5, 0, 0.3}, {1, 0, 0}));
    ASSERT_TRUE(side);
    EXPECT_NEAR(side->t, 4, 1e-6);
    EXPECT_TRUE(finite(side->normal));
    Geometry far(scene_of({make(scene::Superellipsoid{0.5, 0.5}, translate({0, 0, 1e5}))}));
    auto f = trace(far, ray({0, 0, 0}, {0, 0, 1}));
    ASSERT_TRUE(f);
    EXPECT_NEAR(f->t, 1e5 - 1, 1e-6);
    // Negative or NaN exponents: never hit.
    Geometry bad(scene_of({make(scene::Superellipsoid{-1, 1}),
                           make(scene::Superellipsoid{std::nan(""), 1})}));
    EXPECT_FALSE(trace(bad, ray({0, 0, -5}, {0, 0, 1})));
}

// A nearest-hit query stops at the first piece of the ray past a hit it found; every piece
// gives the same nearest hit beyond the query's start, from outside, inside and on the
// surface, for round, boxy and pinched shapes.
TEST(Superellipsoid, TheNearestHitIsTheFullSearchsNearestBeyondTheStart) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    int hits = 0;
    for (const scene::Superellipsoid shape : {scene::Superellipsoid{1, 1},
                                              scene::Superellipsoid{0.2, 0.3},
                                              scene::Superellipsoid{2.5, 1.5}}) {
        const SuperellipsoidShape s = make_superellipsoid(shape);
        for (int i = 0; i < 3000; ++i) {
            const glm::dvec3 o{1.6 * u(rng), 1.6 * u(rng), 1.6 * u(rng)};
            const glm::dvec3 d = glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)));
            const double tmin = i % 2 ? 1e-4 : 0.7 * std::fabs(u(rng));
            // As intersect() asks, along the direction made unit again.
            const double len = glm::length(d);
            double ks[kMaxSuperellipsoidHits];
            const int n = superellipsoid_hits(s, o, d / len, len, ks);
            double nearest = std::numeric_limits<double>::infinity();
            for (int j = 0; j < n; ++j)
                if (ks[j] / len > tmin) nearest = std::min(nearest, ks[j] / len);
            ShapeHit h;
            const bool hit = intersect(s, LocalRay{o, d}, tmin, 1e30, h);
            ASSERT_EQ(hit, nearest < 1e30) << i;
            if (!hit) continue;
            ASSERT_EQ(h.t, nearest) << i;
            ++hits;
        }
    }
    EXPECT_GT(hits, 1500);
}

}  // namespace
}  // namespace lumen::render
