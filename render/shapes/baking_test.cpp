// Baked (world-space) shapes must trace like the object-space shape under its transform.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "render/geometry_test_util.hpp"
#include "render/node.hpp"

namespace lumen::render {
namespace {

using namespace testing;

// Traces random rays at both versions; where both hit, t and the normal must agree.
void expect_same(const scene::Shape& shape, const scene::Transform& xf, const char* what,
                 double normal_tol = 1e-9) {
    ShapeData baked;
    ASSERT_TRUE(bake_transform(shape, xf, baked)) << what;
    ShapeData local;
    ASSERT_TRUE(prepare_shape(shape, true, local)) << what;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    int both = 0, differ = 0;
    for (int i = 0; i < 2000; ++i) {
        glm::dvec3 target = xf.point({u(rng), u(rng), u(rng)});
        glm::dvec3 origin = target + 6.0 * glm::normalize(glm::dvec3{u(rng), u(rng), u(rng)});
        Ray r = ray(origin, target - origin);
        ShapeHit hw, hl;
        bool a = shape_intersect(baked, {r.origin, r.dir}, 1e-6, 1e30, hw);
        bool b = shape_intersect(local, {xf.inv_point(r.origin), xf.inv_vector(r.dir)}, 1e-6, 1e30, hl);
        if (a != b) { ++differ; continue; }  // grazing rays may round either way
        if (!a) continue;
        ++both;
        EXPECT_NEAR(hw.t, hl.t, 1e-9 * (1 + hl.t)) << what << " ray " << i;
        glm::dvec3 nl = glm::normalize(xf.normal(hl.normal)), nw = glm::normalize(hw.normal);
        EXPECT_NEAR(glm::dot(nl, nw), 1, normal_tol) << what << " ray " << i;
    }
    EXPECT_GT(both, 100) << what;
    EXPECT_LE(differ, 4) << what;
}

TEST(ShapeBaking, SimilaritiesForRoundShapes) {
    scene::Transform sim = scale({1.7, 1.7, 1.7}).then(rotate(37, {1, 2, 3})).then(translate({3, -2, 5}));
    scene::Transform mirror = scale({-2, 2, 2}).then(rotate(20, {0, 1, 0})).then(translate({1, 1, 1}));
    for (const auto& xf : {sim, mirror}) {
        expect_same(scene::Sphere{{0.2, 0.1, 0}, 0.8}, xf, "sphere");
        expect_same(scene::Cylinder{{0, -1, 0}, {0.3, 1, 0.2}, 0.5, false}, xf, "cylinder");
        expect_same(scene::Cylinder{{0, -1, 0}, {0.3, 1, 0.2}, 0.5, true}, xf, "open cylinder");
        expect_same(scene::Cone{{0, -1, 0}, 0.8, {0, 1, 0.3}, 0.2, false}, xf, "cone");
        expect_same(scene::Disc{{0, 0, 0}, {0.2, 1, 0}, 1, 0.3}, xf, "disc");
    }
    // A non-uniform scale is not a similarity: the sphere keeps its transform.
    ShapeData out;
    EXPECT_FALSE(bake_transform(scene::Sphere{}, scale({1, 2, 1}), out));
    EXPECT_FALSE(bake_transform(scene::Torus{}, translate({1, 0, 0}), out));
}

TEST(ShapeBaking, AffineMapsForFlatShapesAndAxisScalesForBoxes) {
    scene::Transform shear = from_matrix(glm::dmat4(1, 0.3, 0, 0, 0.2, 1.5, 0.1, 0, 0, 0, -0.8, 0,
                                                    1, 2, 3, 1));
    expect_same(scene::Plane{{0.3, 1, 0.2}, 0.4}, shear, "plane");
    expect_same(scene::Triangle{{glm::dvec3{-1, -1, 0}, {1, -0.5, 0.2}, {0, 1, -0.1}},
                                {glm::dvec3{0, 0, 1}, glm::normalize(glm::dvec3{1, 0, 1}),
                                 glm::normalize(glm::dvec3{0, 1, 1})},
                                true},
                shear, "smooth triangle (mirrored)",
                1e-3);  // POV renormalises each transformed vertex normal before blending
    scene::Polygon p;
    p.points = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {-1, -1, 0},
                {-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0, 0.5, 0}, {-0.5, -0.5, 0}};
    expect_same(p, shear, "polygon with hole");
    expect_same(scene::Box{{-1, -0.5, -0.2}, {0.7, 1, 1}}, scale({2, -0.5, 3}).then(translate({1, 2, 3})),
                "box");
    ShapeData out;
    EXPECT_FALSE(bake_transform(scene::Box{}, rotate(10, {0, 0, 1}), out));
}

}  // namespace
}  // namespace lumen::render
