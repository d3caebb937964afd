// Boxes of quadrics and planes: what a quadric's inside spans within a clip box, the half-space
// box of an axis-aligned plane, and an intersection of both compiled to a finite box (the
// chess pieces of advanced/chess2.pov: cylinders and hyperboloids between planes).
#include <random>

#include <gtest/gtest.h>

#include "render/geometry_test_util.hpp"
#include "render/node.hpp"
#include "render/shapes/plane.hpp"
#include "render/shapes/quadric.hpp"

namespace lumen::render {
namespace {

QuadricShape quadric(glm::dvec3 square, glm::dvec3 linear, double constant) {
    return make_quadric(scene::Quadric{square, glm::dvec3(0), linear, constant});
}

Aabb slab_y(double lo, double hi) {
    Aabb b = Aabb::everything();
    b.lo.y = lo, b.hi.y = hi;
    return b;
}

TEST(QuadricBounds, CylinderBetweenPlanesIsItsRadius) {
    const QuadricShape cylinder = quadric({1, 0, 1}, {0, 0, 0}, -4);  // x² + z² <= 4
    EXPECT_FALSE(bounds(cylinder).finite());  // infinite along y alone
    const Aabb b = bounds_within(cylinder, slab_y(8, 10));
    ASSERT_TRUE(b.finite());
    EXPECT_NEAR(b.lo.x, -2, 1e-5);
    EXPECT_NEAR(b.hi.z, 2, 1e-5);
    EXPECT_EQ(b.lo.y, 8);
    EXPECT_EQ(b.hi.y, 10);
}

TEST(QuadricBounds, ConeAndHyperboloidTakeTheirWidestCircleInTheSlab) {
    const QuadricShape cone = quadric({1, -1, 1}, {0, 0, 0}, 0);  // x² + z² <= y²
    EXPECT_FALSE(bounds(cone).finite());
    EXPECT_NEAR(bounds_within(cone, slab_y(1, 3)).hi.x, 3, 1e-5);
    EXPECT_NEAR(bounds_within(cone, slab_y(-5, 3)).hi.x, 5, 1e-5);
    // Hyperboloid_Y moved up 5: x² + z² <= 1 + (y - 5)² = y² - 10y + 26.
    const QuadricShape hyperboloid = quadric({1, -1, 1}, {0, 10, 0}, -26);
    EXPECT_NEAR(bounds_within(hyperboloid, slab_y(3, 8)).hi.z, std::sqrt(1 + 9.0), 1e-5);
    EXPECT_FALSE(bounds_within(hyperboloid, slab_y(3, Aabb::inf)).finite());
}

TEST(QuadricBounds, EllipsoidAndParaboloid) {
    const Aabb e = bounds(quadric({1, 4, 9}, {2, 0, 0}, -3));  // (x+1)² + 4y² + 9z² <= 4
    ASSERT_TRUE(e.finite());
    EXPECT_NEAR(e.lo.x, -3, 1e-5);
    EXPECT_NEAR(e.hi.x, 1, 1e-5);
    EXPECT_NEAR(e.hi.y, 1, 1e-5);
    EXPECT_NEAR(e.hi.z, 2.0 / 3, 1e-5);
    // x² + z² <= y: open upwards, so bounded by a plane above only.
    const QuadricShape paraboloid = quadric({1, 0, 1}, {0, -1, 0}, 0);
    EXPECT_FALSE(bounds(paraboloid).finite());
    const Aabb p = bounds_within(paraboloid, slab_y(-Aabb::inf, 4));
    ASSERT_TRUE(p.finite());
    EXPECT_NEAR(p.lo.y, 0, 1e-5);
    EXPECT_NEAR(p.hi.x, 2, 1e-5);
    // x² + z² <= -y: open downwards.
    const Aabb down = bounds_within(quadric({1, 0, 1}, {0, 1, 0}, 0), slab_y(-4, Aabb::inf));
    ASSERT_TRUE(down.finite());
    EXPECT_NEAR(down.hi.y, 0, 1e-5);
    EXPECT_NEAR(down.lo.z, -2, 1e-5);
}

TEST(QuadricBounds, MixedTermsKeepTheClip) {
    const QuadricShape tilted = make_quadric(scene::Quadric{{1, 1, 1}, {0.5, 0, 0}, {0, 0, 0}, -1});
    const Aabb clip = slab_y(0, 1);
    const Aabb b = bounds_within(tilted, clip);
    EXPECT_EQ(b.lo, clip.lo);
    EXPECT_EQ(b.hi, clip.hi);
}

TEST(QuadricBounds, HoldEveryInsidePointOfTheClip) {
    // Random axis-aligned quadrics and clip boxes, some sides open: every sampled point of the
    // clip where f <= 0 lies in the box.
    std::mt19937 rng(21);
    std::uniform_real_distribution<double> u(-1, 1);
    std::uniform_int_distribution<int> sign(-1, 1);
    int inside_points = 0;
    for (int q = 0; q < 300; ++q) {
        const QuadricShape s = quadric({sign(rng), sign(rng), sign(rng)},
                                       {2 * u(rng), 2 * u(rng), 2 * u(rng)}, 2 * u(rng));
        Aabb clip = Aabb::everything();
        for (int a = 0; a < 3; ++a) {
            const double c = 3 * u(rng), w = 1 + 3 * (u(rng) + 1);
            if (sign(rng) >= 0) clip.lo[a] = c - w;
            if (sign(rng) >= 0) clip.hi[a] = c + w;
        }
        const Aabb b = bounds_within(s, clip);
        for (int i = 0; i < 2000; ++i) {
            glm::dvec3 p;
            for (int a = 0; a < 3; ++a) {
                const double lo = std::max(clip.lo[a], -40.0), hi = std::min(clip.hi[a], 40.0);
                p[a] = lo + (hi - lo) * (u(rng) + 1) / 2;
            }
            if (!inside(s, p)) continue;
            ++inside_points;
            ASSERT_TRUE(b.contains(p)) << "quadric " << q << " point " << p.x << " " << p.y
                                       << " " << p.z;
        }
    }
    EXPECT_GT(inside_points, 50000);
}

TEST(PlaneBounds, AnAxisAlignedPlaneBoundsItsHalfSpace) {
    const Aabb up = solid_bounds(make_plane(scene::Plane{{0, 2, 0}, 3}));  // y < 3
    EXPECT_NEAR(up.hi.y, 3, 1e-9);
    EXPECT_EQ(up.lo.y, -Aabb::inf);
    EXPECT_EQ(up.hi.x, Aabb::inf);
    const Aabb down = solid_bounds(make_plane(scene::Plane{{0, 0, -1}, 2}));  // z > -2
    EXPECT_NEAR(down.lo.z, -2, 1e-9);
    EXPECT_EQ(down.hi.z, Aabb::inf);
    const Aabb tilted = solid_bounds(make_plane(scene::Plane{{1, 1, 0}, 0}));
    EXPECT_FALSE(tilted.finite());
    EXPECT_EQ(tilted.hi.y, Aabb::inf);
}

TEST(QuadricBounds, AnIntersectionOfACylinderAndPlanesGetsAFiniteBox) {
    using testing::csg;
    using testing::make;
    // The rook's body: intersection { plane { y, 10 } Cylinder_Y scaled 2 plane { -y, -8 } },
    // whose members are each unbounded.
    const auto body = csg(scene::CsgOp::Intersection,
                          {make(scene::Plane{{0, 1, 0}, 10}),
                           make(scene::Quadric{{1, 0, 1}, {0, 0, 0}, {0, 0, 0}, -4}),
                           make(scene::Plane{{0, -1, 0}, -8})});
    NodeStore store;
    const Node& node = store.nodes[compile_object(store, *body, NodeContext{})];
    ASSERT_TRUE(node.surface.finite());
    EXPECT_NEAR(node.surface.hi.x, 2, 1e-5);
    EXPECT_NEAR(node.surface.lo.y, 8, 1e-5);
    // The same hits as ever: the side at radius 2, the top at y = 10.
    const Geometry g(testing::scene_of({body}));
    auto side = testing::trace(g, testing::ray({-5, 9, 0}, {1, 0, 0}));
    ASSERT_TRUE(side);
    EXPECT_NEAR(side->t, 3, 1e-9);
    auto top = testing::trace(g, testing::ray({1, 20, 0}, {0, -1, 0}));
    ASSERT_TRUE(top);
    EXPECT_NEAR(top->t, 10, 1e-9);
    EXPECT_FALSE(testing::trace(g, testing::ray({-5, 11, 0}, {1, 0, 0})));
    EXPECT_FALSE(testing::trace(g, testing::ray({-5, 9, 2.5}, {1, 0, 0})));
}

TEST(PlaneBounds, ASubtractedPlaneCutsTheDifferenceToTheOtherHalfSpace) {
    using testing::csg;
    using testing::make;
    // advanced/abyss's hull: difference { blob plane { y, 0 } plane { z, 0 inverse } }, one
    // octant of the blob each. Subtracted, plane { y, 0 } leaves y >= 0; inverted twice,
    // plane { z, 0 inverse } leaves z <= 0 (the points within 1e-10 of a plane count as
    // inside it, so the bounds sit on the planes).
    const auto part = csg(scene::CsgOp::Difference,
                          {make(scene::Sphere{{0, 0, 0}, 2}), make(scene::Plane{{0, 1, 0}, 0}),
                           [] {
                               auto p = make(scene::Plane{{0, 0, 1}, 0});
                               p->inverse = true;
                               return p;
                           }()});
    NodeStore store;
    const Node& node = store.nodes[compile_object(store, *part, NodeContext{})];
    ASSERT_TRUE(node.surface.finite());
    EXPECT_NEAR(node.surface.lo.y, 0, 1e-9);
    EXPECT_NEAR(node.surface.hi.y, 2, 1e-5);
    EXPECT_NEAR(node.surface.hi.z, 0, 1e-9);
    EXPECT_NEAR(node.surface.lo.z, -2, 1e-5);
    const Aabb half = complement_solid_bounds(make_plane(scene::Plane{{0, -1, 0}, 3}));  // y <= -3
    EXPECT_NEAR(half.hi.y, -3, 1e-9);
    EXPECT_EQ(half.lo.y, -Aabb::inf);
    EXPECT_FALSE(complement_solid_bounds(make_plane(scene::Plane{{1, 1, 0}, 0})).finite());
    // The same hits as without the bound: the sphere's octant and the flat faces.
    const Geometry g(testing::scene_of({part}));
    auto top = testing::trace(g, testing::ray({0.5, 5, -0.5}, {0, -1, 0}));
    ASSERT_TRUE(top);
    EXPECT_NEAR(top->t, 5 - std::sqrt(4 - 0.5), 1e-9);
    auto floor = testing::trace(g, testing::ray({0.5, -5, -0.5}, {0, 1, 0}));
    ASSERT_TRUE(floor);
    EXPECT_NEAR(floor->t, 5, 1e-9);
    auto face = testing::trace(g, testing::ray({0.5, 0.5, 5}, {0, 0, -1}));
    ASSERT_TRUE(face);
    EXPECT_NEAR(face->t, 5, 1e-9);
    EXPECT_FALSE(testing::trace(g, testing::ray({0.5, 5, 0.5}, {0, -1, 0})));
}

}  // namespace
}  // namespace lumen::render
