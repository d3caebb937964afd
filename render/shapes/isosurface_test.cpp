// isosurface details POV-Ray shows that the generic shape properties do not: the flat face
// where a closed container cuts the solid, the open surface seen through, max_trace, and the
// gradient warning after a render.
#include "render/shapes/isosurface.hpp"

#include <gtest/gtest.h>

namespace lumen::render {
namespace {

using fn::Op;

// x² + y² + z² - r² (a sphere of radius r) as a program.
fn::ProgramPtr sphere_function(double r) {
    auto p = std::make_shared<fn::Program>();
    p->consts = {r * r};
    p->code = {{Op::Arg, 0, 0, 0}, {Op::Arg, 0, 0, 0}, {Op::Mul}, {Op::Arg, 0, 0, 1},
               {Op::Arg, 0, 0, 1}, {Op::Mul},          {Op::Add}, {Op::Arg, 0, 0, 2},
               {Op::Arg, 0, 0, 2}, {Op::Mul},          {Op::Add}, {Op::SubConst, 0, 0, 0}};
    return p;
}

IsosurfaceShape shape(double radius, bool open, int max_trace = 1, double max_gradient = 5) {
    scene::Isosurface s;
    s.function = sphere_function(radius);
    s.open = open;
    s.max_trace = max_trace;
    s.max_gradient = max_gradient;
    return make_isosurface(s);  // box -1..1
}

TEST(Isosurface, ClosedContainerCutsWithAFlatFace) {
    // A sphere of radius 1.2 in the box -1..1: along the x axis the solid fills the box, so
    // the ray stops at the box's face x = -1 with the face's normal.
    const IsosurfaceShape s = shape(1.2, false);
    ShapeHit h;
    ASSERT_TRUE(intersect(s, {{-3, 0, 0}, {1, 0, 0}}, 1e-4, 1e9, h));
    EXPECT_NEAR(h.t, 2, 1e-12);
    EXPECT_EQ(h.normal, glm::dvec3(-1, 0, 0));
}

TEST(Isosurface, OpenSurfaceIsHollowWhereTheContainerCutsIt) {
    // Open: the ray passes the cut and finds the sphere's far side from inside (the box corner
    // region outside the sphere is empty, so only the exit of the solid is left: none here).
    const IsosurfaceShape s = shape(1.2, true);
    ShapeHit h;
    EXPECT_FALSE(intersect(s, {{-3, 0, 0}, {1, 0, 0}}, 1e-4, 1e9, h));
    // Along a diagonal the sphere's surface lies inside the box: found, within the accuracy.
    const glm::dvec3 d = glm::normalize(glm::dvec3(1, 1, 1));
    ASSERT_TRUE(intersect(s, {-3.0 * d, d}, 1e-4, 1e9, h));
    EXPECT_NEAR(h.t, 3 - 1.2, 1e-3);
    EXPECT_GT(glm::dot(h.normal, -d), 0.99);
}

TEST(Isosurface, MaxTraceBoundsTheCrossingsARayReports) {
    const glm::dvec3 d(1, 0, 0);
    IsoHit hits[kMaxIsoHits];
    EXPECT_EQ(isosurface_hits(shape(0.5, false, 1), {{-3, 0, 0}, d}, hits), 1);
    ASSERT_EQ(isosurface_hits(shape(0.5, false, 2), {{-3, 0, 0}, d}, hits), 2);
    EXPECT_NEAR(hits[0].t, 2.5, 1e-3);
    EXPECT_NEAR(hits[1].t, 3.5, 1e-3);
}

TEST(Isosurface, WarnsAfterARenderWhenMaxGradientIsOff) {
    // The slopes the bisection meets between interval ends: 1.5 where max_gradient 1 lets it
    // split, up to 1.97 at 50. At 0.5 it never splits and finds no slope: no warning (POV's).
    for (const auto& [max_gradient, warns, holes] :
         {std::tuple{0.5, false, false}, std::tuple{1.0, true, true}, std::tuple{2.0, false, false},
          std::tuple{50.0, true, false}}) {
        const IsosurfaceShape s = shape(0.5, false, 1, max_gradient);
        IsoHit hits[kMaxIsoHits];
        for (int i = 0; i < 50; ++i) {
            IsosurfaceShape alone = s;  // the slopes are shared; a new cache key: every search runs
            alone.id = 1'000'000 + i;
            isosurface_hits(alone, {{-3, -0.9 + 0.036 * i, 0.3}, {1, 0, 0}}, hits);
        }
        const auto w = gradient_warning(s);
        EXPECT_EQ(bool(w), warns) << max_gradient;
        if (w) {
            EXPECT_EQ(w->find("may contain holes") != std::string::npos, holes) << *w;
        }
    }
}

// POV-Ray's cross-ray cache: after a failed search, a search on the same object whose ends
// lie within fmin / max_gradient of the failed one's is skipped. With a max_gradient that
// holds it skips only true misses; with one too low it skips hits (POV-Ray's holes).
TEST(Isosurface, AFailedSearchSkipsNearbySearches) {
    const LocalRay miss{{-3, 0.9, 0}, {1, 0, 0}}, hit{{-3, 0.45, 0}, {1, 0, 0}};
    IsoHit hits[kMaxIsoHits];
    const IsosurfaceShape low = shape(0.5, false, 1, 1.0);  // |grad| reaches 2.7 in the box
    EXPECT_EQ(isosurface_hits(low, hit, hits), 1);  // found when nothing failed before
    EXPECT_EQ(isosurface_hits(low, miss, hits), 0);
    EXPECT_EQ(isosurface_hits(low, hit, hits), 0);  // skipped: the miss's bound rules it out
    const IsosurfaceShape right = shape(0.5, false, 1, 8.0);
    EXPECT_EQ(isosurface_hits(right, miss, hits), 0);
    EXPECT_EQ(isosurface_hits(right, hit, hits), 1);  // a true bound does not rule it out
    {
        const ShadowRayMark shadow(true);  // a shadow ray's failure is not remembered
        EXPECT_EQ(isosurface_hits(low, miss, hits), 0);
    }
    EXPECT_EQ(isosurface_hits(low, hit, hits), 1);
}

}  // namespace
}  // namespace lumen::render
