// Per-shape robustness: stable roots, grazing rays, parallel rays, degenerate input.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "render/geometry_test_util.hpp"
#include "render/shapes.hpp"

namespace lumen::render {
namespace {

using namespace testing;

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

TEST(Sphere, HitAndNormal) {
    Geometry g(scene_of({make(scene::Sphere{{0, 0, 5}, 1})}));
    auto h = trace(g, ray({0, 0, 0}, {0, 0, 1}));
    ASSERT_TRUE(h);
    EXPECT_DOUBLE_EQ(h->t, 4);
    EXPECT_NEAR(h->normal.z, -1, 1e-15);
    EXPECT_FALSE(trace(g, ray({0, 0, 0}, {0, 1, 0})));
}

TEST(Sphere, FarAwayKeepsRelativePrecision) {
    const double d = 1e6;
    Geometry g(scene_of({make(scene::Sphere{{0, 0, d}, 1})}));
    auto h = trace(g, ray({0, 0, 0}, {0, 0, 1}));
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, d - 1, (d - 1) * 1e-9);
    // Off-centre: exact answer d - sqrt(1 - 0.6^2) = d - 0.8.
    auto h2 = trace(g, ray({0.6, 0, 0}, {0, 0, 1}));
    ASSERT_TRUE(h2);
    EXPECT_NEAR(h2->t, d - 0.8, d * 1e-9);
    EXPECT_NEAR(h2->normal.x, 0.6, 1e-6);
}

TEST(Sphere, GrazingRaysGiveNoNaN) {
    Geometry g(scene_of({make(scene::Sphere{{0, 0, 0}, 1})}));
    for (double y : {1 - 1e-12, 1.0, 1 + 1e-12, std::nextafter(1.0, 2.0)}) {
        Hit h;
        bool hit = g.intersect(ray({-5, y, 0}, {1, 0, 0}), 1e-4, 1e30, h);
        if (hit) {
            EXPECT_TRUE(std::isfinite(h.t));
            EXPECT_TRUE(finite(h.normal));
            EXPECT_NEAR(glm::length(h.normal), 1, 1e-9);
        }
        if (y > 1) { EXPECT_FALSE(hit); }
    }
    EXPECT_TRUE(trace(g, ray({-5, 1 - 1e-9, 0}, {1, 0, 0})));
}

TEST(Sphere, RayLeavingFromSurfaceSkipsItsOrigin) {
    Geometry g(scene_of({make(scene::Sphere{{0, 0, 0}, 1})}));
    // From the surface outward: nothing; inward: the far side at 2.
    EXPECT_FALSE(trace(g, ray({0, 0, -1}, {0, 0, -1})));
    auto h = trace(g, ray({0, 0, -1}, {0, 0, 1}));
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 2, 1e-12);
    EXPECT_NEAR(h->normal.z, 1, 1e-12);  // outward, not towards the ray
}

TEST(Plane, ParallelRaysMissWithoutNaN) {
    Geometry g(scene_of({make(scene::Plane{{0, 1, 0}, 0})}));
    EXPECT_FALSE(trace(g, ray({0, 1, 0}, {1, 0, 0})));
    EXPECT_FALSE(trace(g, ray({0, 0, 0}, {1, 0, 0})));  // in the plane
    auto h = trace(g, ray({0, 2, 0}, {0, -1, 1}));
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 2 * std::sqrt(2.0), 1e-12);
    EXPECT_EQ(h->normal, glm::dvec3(0, 1, 0));
}

TEST(Plane, DistanceAlongUnnormalisedNormal) {
    // plane { <0,2,0>, 3 }: n is normalised, d is not divided: y = 3.
    Geometry g(scene_of({make(scene::Plane{{0, 2, 0}, 3})}));
    auto h = trace(g, ray({0, 10, 0}, {0, -1, 0}));
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 7, 1e-12);
    EXPECT_TRUE(Geometry::inside(*make(scene::Plane{{0, 1, 0}, 0}), {0, -1, 0}));
    EXPECT_FALSE(Geometry::inside(*make(scene::Plane{{0, 1, 0}, 0}), {0, 1, 0}));
}

TEST(Box, FacesAndNormals) {
    Geometry g(scene_of({make(scene::Box{{1, 1, 1}, {-1, -1, -1}})}));  // corners reordered
    auto h = trace(g, ray({0, 0, -5}, {0, 0, 1}));
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 4, 1e-12);
    EXPECT_EQ(h->normal, glm::dvec3(0, 0, -1));
    auto inside_hit = trace(g, ray({0, 0, 0}, {1, 0, 0}));
    ASSERT_TRUE(inside_hit);
    EXPECT_NEAR(inside_hit->t, 1, 1e-12);
    EXPECT_EQ(inside_hit->normal, glm::dvec3(1, 0, 0));
    auto diag = trace(g, ray({-5, 0.5, 0.5}, {1, 0, 0}));
    ASSERT_TRUE(diag);
    EXPECT_EQ(diag->normal, glm::dvec3(-1, 0, 0));
}

TEST(Box, GrazingAlongAFaceIsConsistent) {
    Geometry g(scene_of({make(scene::Box{{-1, -1, -1}, {1, 1, 1}})}));
    // Rays in the plane y = 1 (exactly on the top face), zero y direction component.
    for (double x0 : {-5.0, -3.0}) {
        Hit h;
        bool hit = g.intersect(ray({x0, 1, 0}, {1, 0, 0}), 1e-4, 1e30, h);
        if (hit) {
            EXPECT_TRUE(std::isfinite(h.t));
            EXPECT_TRUE(finite(h.normal));
            EXPECT_NEAR(h.t, -1 - x0, 1e-12);
        }
        Hit h2;
        EXPECT_EQ(hit, g.intersect(ray({x0, 1, 0.5}, {1, 0, 0}), 1e-4, 1e30, h2));
    }
    // Along an edge and through a corner.
    Hit h;
    if (g.intersect(ray({-5, 1, 1}, {1, 0, 0}), 1e-4, 1e30, h)) { EXPECT_TRUE(finite(h.normal)); }
    auto corner = trace(g, ray({-2, -2, -2}, {1, 1, 1}));
    ASSERT_TRUE(corner);
    EXPECT_NEAR(corner->t, std::sqrt(3.0), 1e-12);
    EXPECT_TRUE(finite(corner->normal));
}

TEST(Cylinder, CappedAndOpen) {
    scene::Cylinder c{{0, 0, 0}, {0, 2, 0}, 0.5, false};
    Geometry capped(scene_of({make(c)}));
    auto side = trace(capped, ray({-5, 1, 0}, {1, 0, 0}));
    ASSERT_TRUE(side);
    EXPECT_NEAR(side->t, 4.5, 1e-12);
    EXPECT_NEAR(side->normal.x, -1, 1e-12);
    auto cap = trace(capped, ray({0.1, 5, 0}, {0, -1, 0}));
    ASSERT_TRUE(cap);
    EXPECT_NEAR(cap->t, 3, 1e-12);
    EXPECT_NEAR(cap->normal.y, 1, 1e-12);
    c.open = true;
    Geometry open(scene_of({make(c)}));
    auto through = trace(open, ray({0.1, 5, 0}, {0, -1, 0}));
    EXPECT_FALSE(through);  // straight down the open tube
    auto inner = trace(open, ray({0, 1, 0}, {1, 0, 0}));
    ASSERT_TRUE(inner);
    EXPECT_NEAR(inner->t, 0.5, 1e-12);
    EXPECT_TRUE(Geometry::inside(*make(c), {0.2, 1, 0}));
    EXPECT_FALSE(Geometry::inside(*make(c), {0.2, 2.5, 0}));
}

TEST(Cylinder, ArbitraryAxis) {
    scene::Cylinder c{{1, 1, 1}, {3, 3, 3}, 0.5, false};
    Geometry g(scene_of({make(c)}));
    // Along the axis from outside: hits the base cap at distance |(1,1,1)| from the origin.
    auto h = trace(g, ray({0, 0, 0}, {1, 1, 1}));
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, std::sqrt(3.0), 1e-12);
    EXPECT_NEAR(glm::dot(h->normal, glm::normalize(glm::dvec3(-1, -1, -1))), 1, 1e-12);
}

TEST(Cone, SideCapsAndApex) {
    scene::Cone c{{0, 0, 0}, 1, {0, 1, 0}, 0, false};
    Geometry g(scene_of({make(c)}));
    auto h = trace(g, ray({-5, 0.5, 0}, {1, 0, 0}));
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 4.5, 1e-12);  // radius 0.5 at half height
    EXPECT_NEAR(h->normal.x, -std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(h->normal.y, std::sqrt(0.5), 1e-12);
    auto base = trace(g, ray({0.2, -3, 0}, {0, 1, 0}));
    ASSERT_TRUE(base);
    EXPECT_NEAR(base->t, 3, 1e-12);
    EXPECT_NEAR(base->normal.y, -1, 1e-12);
    EXPECT_FALSE(trace(g, ray({-5, 1.5, 0}, {1, 0, 0})));  // above the apex: the other nappe
    EXPECT_TRUE(Geometry::inside(*make(c), {0.2, 0.5, 0}));
    EXPECT_FALSE(Geometry::inside(*make(c), {0.6, 0.5, 0}));
}

// Brute-force reference for the torus: sample the implicit function along the ray.
double first_root_by_scan(double R, double r, const Ray& ray, double tmax) {
    auto f = [&](double t) {
        glm::dvec3 p = ray.at(t);
        double g = glm::dot(p, p) + R * R - r * r;
        return g * g - 4 * R * R * (p.x * p.x + p.z * p.z);
    };
    const int steps = 200000;
    double prev = f(1e-4);
    for (int i = 1; i <= steps; ++i) {
        double t = 1e-4 + tmax * i / steps;
        double v = f(t);
        if ((v < 0) != (prev < 0)) return t;
        prev = v;
    }
    return -1;
}

TEST(Torus, MatchesBruteForceRootSearch) {
    const double R = 2, r = 0.5;
    Geometry g(scene_of({make(scene::Torus{R, r, false})}));
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    int hits = 0;
    for (int i = 0; i < 60; ++i) {
        glm::dvec3 o{u(rng) * 6, u(rng) * 3, u(rng) * 6};
        glm::dvec3 target{u(rng) * 2.5, u(rng) * 0.6, u(rng) * 2.5};
        Ray rr = ray(o, target - o);
        double expected = first_root_by_scan(R, r, rr, 15);
        auto h = trace(g, rr);
        if (expected < 0) {
            EXPECT_FALSE(h) << i;
            continue;
        }
        ASSERT_TRUE(h) << i;
        ++hits;
        EXPECT_NEAR(h->t, expected, 15.0 / 200000 * 1.01) << i;
        // The normal points away from the tube centre.
        glm::dvec3 ring = glm::normalize(glm::dvec3(h->point.x, 0, h->point.z)) * R;
        EXPECT_NEAR(glm::dot(h->normal, glm::normalize(h->point - ring)), 1, 1e-9);
    }
    EXPECT_GT(hits, 20);
}

// A large thin ring (an arch moulding of radiosity/patio-radio_37.pov): most rays through its
// bounding sphere cross the ring's plane far from the tube, which a test before the quartic
// rejects; it must reject nothing the quartic would find, grazing rays along the tube included.
TEST(Torus, ThinRingMatchesBruteForceRootSearch) {
    const double R = 130, r = 2;
    Geometry g(scene_of({make(scene::Torus{R, r, false})}));
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    int hits = 0, misses = 0;
    for (int i = 0; i < 120; ++i) {
        glm::dvec3 o{u(rng) * 200, u(rng) * 60, u(rng) * 200};
        // Aim near the tube (within twice its radius), anywhere round the ring, or, one ray in
        // four, anywhere in the bounding sphere.
        const double phi = 3.14159265358979 * u(rng);
        glm::dvec3 target{(R + 2 * r * u(rng)) * std::cos(phi), 2 * r * u(rng),
                          (R + 2 * r * u(rng)) * std::sin(phi)};
        if (i % 4 == 0) target = {u(rng) * 130, u(rng) * 130, u(rng) * 130};
        if (i % 10 == 0) o.y = r * 0.999;  // in the tube's top plane: a long grazing span
        Ray rr = ray(o, target - o);
        const double tmax = 700;
        double expected = first_root_by_scan(R, r, rr, tmax);
        auto h = trace(g, rr);
        if (expected < 0) {
            EXPECT_FALSE(h) << i;
            ++misses;
            continue;
        }
        ASSERT_TRUE(h) << i;
        ++hits;
        EXPECT_NEAR(h->t, expected, tmax / 200000 * 1.01) << i;
    }
    EXPECT_GT(hits, 30);
    EXPECT_GT(misses, 20);
}

TEST(Torus, GrazingTopAndDistantRays) {
    const double R = 2, r = 0.5;
    Geometry g(scene_of({make(scene::Torus{R, r, false})}));
    // Just under the top of the tube: two close roots near x = -2; tangent: finite or none.
    auto under = trace(g, ray({-10, r - 1e-7, 0}, {1, 0, 0}));
    ASSERT_TRUE(under);
    EXPECT_NEAR(under->t, 8, 1e-3);
    EXPECT_TRUE(finite(under->normal));
    Hit h;
    if (g.intersect(ray({-10, r, 0}, {1, 0, 0}), 1e-4, 1e30, h)) { EXPECT_TRUE(finite(h.normal)); }
    EXPECT_FALSE(trace(g, ray({-10, r + 1e-7, 0}, {1, 0, 0})));
    // From far away along x: first hit at the outer equator.
    auto far = trace(g, ray({-1e5, 0, 0}, {1, 0, 0}));
    ASSERT_TRUE(far);
    EXPECT_NEAR(far->t, 1e5 - 2.5, 1e-6);
    // Through the hole along y: nothing.
    EXPECT_FALSE(trace(g, ray({0, 10, 0}, {0, -1, 0})));
    EXPECT_TRUE(Geometry::inside(*make(scene::Torus{R, r, false}), {2.2, 0.1, 0}));
    EXPECT_FALSE(Geometry::inside(*make(scene::Torus{R, r, false}), {0, 0, 0}));
}

TEST(Disc, HoleAndRadius) {
    Geometry g(scene_of({make(scene::Disc{{0, 0, 0}, {0, 0, 1}, 1, 0.5})}));
    EXPECT_FALSE(trace(g, ray({0, 0, -1}, {0, 0, 1})));      // in the hole
    EXPECT_FALSE(trace(g, ray({1.2, 0, -1}, {0, 0, 1})));    // outside
    auto h = trace(g, ray({0.7, 0, -1}, {0, 0, 1}));
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 1, 1e-12);
    // POV-Ray's inside of a disc: the half-space behind it, however far from the rim.
    EXPECT_TRUE(Geometry::inside(*make(scene::Disc{}), {0, -0.1, 0}));
    EXPECT_TRUE(Geometry::inside(*make(scene::Disc{}), {50, -0.1, -50}));
    EXPECT_FALSE(Geometry::inside(*make(scene::Disc{}), {0, 0.1, 0}));
}

// POV-Ray's disc box, as povray showed it through an intersection of a big box with a disc
// (orthographic views, 0.01 per pixel): normal y gives the radius across and 0.001 either side
// of the plane; normal <1, 2, 3>, radius 1, gives half-widths 1.04, 0.92 and 0.80 (the tightest
// box would be 0.96, 0.85 and 0.60). It scales with the disc.
TEST(Disc, BoxIsPovRaysSquareInTheDiscsFrame) {
    Aabb flat = bounds(make_disc(scene::Disc{{1, 2, 3}, {0, -1, 0}, 10.1, 0}));
    EXPECT_NEAR(flat.lo.x, 1 - 10.1, 1e-12);
    EXPECT_NEAR(flat.hi.z, 3 + 10.1, 1e-12);
    EXPECT_NEAR(flat.lo.y, 2 - 1e-3, 1e-12);
    EXPECT_NEAR(flat.hi.y, 2 + 1e-3, 1e-12);
    Aabb tilted = bounds(make_disc(scene::Disc{{0, 0, 0}, {1, 2, 3}, 1, 0}));
    const glm::dvec3 measured(1.04, 0.92, 0.80);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(tilted.hi[i], measured[i], 0.01) << i;
        EXPECT_NEAR(tilted.lo[i], -measured[i], 0.01) << i;
    }
    DiscShape scaled;
    ASSERT_TRUE(ShapeTraits<scene::Disc>::bake(scene::Disc{{0, 0, 0}, {0, 1, 0}, 5, 0},
                                               scale({3, 3, 3}), scaled));
    EXPECT_NEAR(bounds(scaled).hi.y, 3e-3, 1e-12);
    // Facing -z, where the rotation onto the normal is half a turn: still the square.
    Aabb back = bounds(make_disc(scene::Disc{{0, 0, 0}, {0, 0, -1}, 2, 0}));
    EXPECT_NEAR(back.hi.x, 2, 1e-12);
    EXPECT_NEAR(back.hi.y, 2, 1e-12);
    EXPECT_NEAR(back.hi.z, 1e-3, 1e-12);
}

TEST(Triangle, TwoSidedFlatAndSmooth) {
    scene::Triangle t;
    t.p = {glm::dvec3{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    Geometry g(scene_of({make(t)}));
    auto front = trace(g, ray({0.2, 0.2, -1}, {0, 0, 1}));
    auto back = trace(g, ray({0.2, 0.2, 1}, {0, 0, -1}));
    ASSERT_TRUE(front && back);
    EXPECT_NEAR(front->t, 1, 1e-12);
    EXPECT_EQ(front->normal, back->normal);  // not flipped towards the ray
    EXPECT_NEAR(std::abs(front->normal.z), 1, 1e-12);
    EXPECT_FALSE(trace(g, ray({0.6, 0.6, -1}, {0, 0, 1})));
    t.smooth = true;
    t.n = {glm::dvec3{0, 0, 1}, glm::normalize(glm::dvec3{1, 0, 1}), glm::normalize(glm::dvec3{0, 1, 1})};
    Geometry gs(scene_of({make(t)}));
    auto s = trace(gs, ray({0.5, 0, -1}, {0, 0, 1}));  // halfway between vertices 0 and 1
    ASSERT_TRUE(s);
    EXPECT_NEAR(glm::length(s->normal), 1, 1e-12);
    glm::dvec3 expect = glm::normalize(glm::dvec3(0, 0, 1) + glm::normalize(glm::dvec3{1, 0, 1}));
    EXPECT_NEAR(glm::dot(s->normal, expect), 1, 1e-12);
}

// Rays aimed at points of an edge two triangles share (a fan around an axis, as a lathed
// mesh has, seen by rays in the axis's plane) hit one of the two: no crack lets them through.
TEST(Triangle, RaysThroughASharedEdgeHitOneSide) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> U(-1, 1);
    int strict_misses = 0, misses = 0;
    for (int i = 0; i < 20000; ++i) {
        const glm::dvec3 a(U(rng), U(rng), U(rng)), b(U(rng), U(rng), U(rng));
        const glm::dvec3 c = a + glm::dvec3(U(rng), U(rng), U(rng));
        const glm::dvec3 d = a + glm::dvec3(U(rng), U(rng), U(rng));
        TriangleCore t1, t2;
        if (!make_triangle_core(a, b, c, t1) || !make_triangle_core(b, a, d, t2)) continue;
        // c and d on opposite sides of the edge, as in a surface.
        const glm::dvec3 n = glm::cross(b - a, glm::cross(c - a, b - a));
        if (glm::dot(n, c - a) * glm::dot(n, d - a) >= 0) continue;
        const double s = 0.5 + 0.4 * U(rng);
        const glm::dvec3 target = a + s * (b - a);
        const glm::dvec3 origin(U(rng) * 5, U(rng) * 5, U(rng) * 5);
        const LocalRay r{origin, target - origin};
        double t, u, v;
        const int strict = int(hit_triangle(t1, r, 1e-6, 1e30, t, u, v, 0)) +
                           int(hit_triangle(t2, r, 1e-6, 1e30, t, u, v, 0));
        const int slack = int(hit_triangle(t1, r, 1e-6, 1e30, t, u, v)) +
                          int(hit_triangle(t2, r, 1e-6, 1e30, t, u, v));
        strict_misses += strict == 0;
        misses += slack == 0;
    }
    EXPECT_GT(strict_misses, 0);  // rounding does open cracks without the slack
    EXPECT_EQ(misses, 0);
}

TEST(Triangle, DegenerateIsSkipped) {
    scene::Triangle t;
    t.p = {glm::dvec3{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};  // collinear: zero area
    scene::Triangle n;
    n.p = {glm::dvec3{0, 0, 0}, {NAN, 0, 0}, {0, 1, 0}};
    Geometry g(scene_of({make(t), make(n), make(scene::Sphere{{0, 0, 0}, 0})}));
    EXPECT_FALSE(trace(g, ray({1, 1, 0}, {0, 0, 1})));
    EXPECT_FALSE(trace(g, ray({-1, 0, -0.5}, {1, 0.5, 1})));
    EXPECT_FALSE(trace(g, ray({0, 0, -1}, {0, 0, 1})));
}

TEST(Polygon, EvenOddWithHole) {
    // A 4x4 square with a 2x2 square hole, sub-polygons closed by repeating their first point.
    scene::Polygon p;
    p.points = {{-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0}, {-2, -2, 0},
                {-1, -1, 0}, {1, -1, 0}, {1, 1, 0},  {-1, 1, 0}, {-1, -1, 0}};
    Geometry g(scene_of({make(p)}));
    EXPECT_FALSE(trace(g, ray({0, 0, -1}, {0, 0, 1})));    // the hole
    EXPECT_FALSE(trace(g, ray({3, 0, -1}, {0, 0, 1})));    // outside
    auto h = trace(g, ray({1.5, 0.3, -1}, {0, 0, 1}));
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 1, 1e-12);
    EXPECT_NEAR(std::abs(h->normal.z), 1, 1e-12);
    EXPECT_FALSE(trace(g, ray({1.5, 0.3, 0}, {1, 0, 0})));  // parallel, in plane
}

TEST(Polygon, TiltedConcave) {
    // An L shape in the plane x + z = 1 (projection must drop a dominant axis correctly).
    scene::Polygon p;
    p.points = {{0, 0, 1}, {1, 0, 0}, {1, 1, 0}, {0.5, 1, 0.5}, {0.5, 0.5, 0.5}, {0, 0.5, 1}, {0, 0, 1}};
    Geometry g(scene_of({make(p)}));
    EXPECT_TRUE(trace(g, ray({-1, 0.25, -1}, {1, 0, 1})));   // the foot
    EXPECT_FALSE(trace(g, ray({-1, 0.75, -0.5}, {1, 0, 1})));  // notch of the L (x = 0.25)
    EXPECT_TRUE(trace(g, ray({-0.5, 0.75, -1}, {1, 0, 1})));   // upright (x = 0.75)
}

// A glyph like 'O': a 1x1 square with a square hole, wound as TrueType winds outlines (outer
// clockwise, hole counter-clockwise), beside a blank glyph, extruded 0.5 deep.
scene::Text square_o() {
    scene::Text t;
    t.thickness = 0.5;
    scene::Text::Glyph o;
    o.points = {{{0, 0}, true},     {{0, 1}, true},     {{1, 1}, true},     {{1, 0}, true},
                {{0.25, 0.25}, true}, {{0.75, 0.25}, true}, {{0.75, 0.75}, true},
                {{0.25, 0.75}, true}};
    o.contour_ends = {4, 8};
    scene::Text::Glyph blank;
    blank.position = {2, 0, 0};
    t.glyphs = {o, blank};
    return t;
}

TEST(Text, FacesWallsAndTheHole) {
    Geometry g(scene_of({make(square_o())}));
    auto front = trace(g, ray({0.1, 0.5, -1}, {0, 0, 1}));
    ASSERT_TRUE(front);
    EXPECT_NEAR(front->t, 1, 1e-12);
    EXPECT_NEAR(front->normal.z, -1, 1e-12);
    auto back = trace(g, ray({0.1, 0.5, 2}, {0, 0, -1}));
    ASSERT_TRUE(back);
    EXPECT_NEAR(back->t, 1.5, 1e-12);
    EXPECT_NEAR(back->normal.z, 1, 1e-12);
    EXPECT_FALSE(trace(g, ray({0.5, 0.5, -1}, {0, 0, 1})));  // through the hole
    EXPECT_FALSE(trace(g, ray({2.5, 0.5, -1}, {0, 0, 1})));  // the blank glyph
    // Along x at mid-depth: the outer wall (normal -x, outward), then the hole's wall (+x).
    auto wall = trace(g, ray({-1, 0.5, 0.25}, {1, 0, 0}));
    ASSERT_TRUE(wall);
    EXPECT_NEAR(wall->t, 1, 1e-12);
    EXPECT_NEAR(wall->normal.x, -1, 1e-12);
    auto hole = trace(g, ray({0.5, 0.5, 0.25}, {1, 0, 0}));
    ASSERT_TRUE(hole);
    EXPECT_NEAR(hole->t, 0.25, 1e-12);
    EXPECT_NEAR(hole->normal.x, -1, 1e-12);  // out of the material, into the hole
    const auto o = make(square_o());
    EXPECT_TRUE(Geometry::inside(*o, {0.1, 0.5, 0.25}));
    EXPECT_FALSE(Geometry::inside(*o, {0.5, 0.5, 0.25}));
    EXPECT_FALSE(Geometry::inside(*o, {0.1, 0.5, 0.6}));
}

TEST(Text, RaysAlongTheExtrusionAndGrazingTheCaps) {
    Geometry g(scene_of({make(square_o())}));
    // Parallel to the walls, exactly on a wall's line: the caps decide, without NaN.
    for (double x : {0.0, 0.25, 1.0, std::nextafter(1.0, 2.0)}) {
        Hit h;
        if (g.intersect(ray({x, 0.5, -1}, {0, 0, 1}), 1e-6, 1e30, h)) {
            EXPECT_TRUE(std::isfinite(h.t) && finite(h.normal));
            EXPECT_NEAR(h.t, 1, 1e-12);
        }
    }
    EXPECT_FALSE(trace(g, ray({1 + 1e-9, 0.5, -1}, {0, 0, 1})));
    // Parallel to the caps: in them (z = 0, z = thickness) the walls still count, just
    // outside they do not.
    for (double z : {0.0, 0.5}) {
        auto h = trace(g, ray({-1, 0.1, z}, {1, 0, 0}));
        ASSERT_TRUE(h) << z;
        EXPECT_NEAR(h->t, 1, 1e-12);
    }
    EXPECT_FALSE(trace(g, ray({-1, 0.1, -1e-9}, {1, 0, 0})));
    EXPECT_FALSE(trace(g, ray({-1, 0.1, 0.5 + 1e-9}, {1, 0, 0})));
}

TEST(Text, TangentToACurvedWallMisses) {
    // A quadratic bump from (0,0) over (0.5,1) to (1,0), closed by its chord: its top is at
    // y = 0.5. POV-Ray's glyph solver has no root at a tangent, so the ray along the top misses.
    scene::Text t;
    scene::Text::Glyph bump;
    bump.points = {{{0, 0}, true}, {{0.5, 1}, false}, {{1, 0}, true}};
    bump.contour_ends = {3};
    t.glyphs = {bump};
    Geometry g(scene_of({make(t)}));
    EXPECT_FALSE(trace(g, ray({-1, 0.5, 0.5}, {1, 0, 0})));
    auto below = trace(g, ray({-1, 0.4, 0.5}, {1, 0, 0}));
    ASSERT_TRUE(below);
    const double s = (1 - std::sqrt(1 - 0.8)) / 2;  // y(s) = 2s(1-s) = 0.4
    EXPECT_NEAR(below->t, 1 + s, 1e-12);
    EXPECT_LT(below->normal.x, 0);
}

TEST(Text, EmptyTextIsNeverHit) {
    scene::Text empty;
    Geometry g(scene_of({make(empty)}));
    EXPECT_FALSE(trace(g, ray({0, 0, -1}, {0, 0, 1})));
    EXPECT_FALSE(Geometry::inside(*make(empty), {0, 0, 0}));
    EXPECT_TRUE(bounds(make_text(empty)).empty());
}

}  // namespace
}  // namespace lumen::render
