// prism, lathe and sor: hits where POV-Ray puts them, and the rays that strain the solvers:
// parallel to the sweep or the axis, grazing walls, through cap edges, far away.
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "render/geometry_test_util.hpp"
#include "render/shapes.hpp"

namespace lumen::render {
namespace {

using namespace testing;

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// A unit square (x, z in [-0.5, 0.5]) with a square hole (|x|, |z| < 0.2), from y = 0 to 1.
scene::Prism square_with_hole() {
    scene::Prism p;
    p.points = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}, {-0.5, -0.5},
                {-0.2, -0.2}, {0.2, -0.2}, {0.2, 0.2}, {-0.2, 0.2}, {-0.2, -0.2}};
    return p;
}

TEST(Prism, RaysParallelToTheSweepSeeOnlyTheCaps) {
    Geometry g(scene_of({make(square_with_hole())}));
    auto top = trace(g, ray({0.3, 3, 0.1}, {0, -1, 0}));
    ASSERT_TRUE(top);
    EXPECT_NEAR(top->t, 2, 1e-12);
    EXPECT_NEAR(top->normal.y, 1, 1e-12);
    auto base = trace(g, ray({0.3, -2, 0.1}, {0, 1, 0}));
    ASSERT_TRUE(base);
    EXPECT_NEAR(base->t, 2, 1e-12);
    EXPECT_FALSE(trace(g, ray({0, 3, 0}, {0, -1, 0})));    // down the hole
    EXPECT_FALSE(trace(g, ray({0.6, 3, 0}, {0, -1, 0})));  // beside it
    // Exactly down a wall's plane: whatever is hit is finite (no wall root: D is parallel).
    for (double x : {-0.5, -0.2, 0.2, 0.5}) {
        Hit h;
        if (g.intersect(ray({x, 3, 0.35}, {0, -1, 0}), 1e-4, 1e30, h)) {
            EXPECT_TRUE(std::isfinite(h.t) && finite(h.normal));
            EXPECT_NEAR(h.t, 2, 1e-12);
        }
    }
}

TEST(Prism, WallsFaceOutAndHolesFaceIn) {
    Geometry g(scene_of({make(square_with_hole())}));
    auto outer = trace(g, ray({-2, 0.5, 0.35}, {1, 0, 0}));
    ASSERT_TRUE(outer);
    EXPECT_NEAR(outer->t, 1.5, 1e-12);
    EXPECT_LT(outer->normal.x, 0);
    auto hole = trace(g, ray({-2, 0.5, 0}, {1, 0, 0}));  // the outer wall, then the hole's
    ASSERT_TRUE(hole);
    auto into = trace(g, ray({-0.3, 0.5, 0}, {1, 0, 0}));
    ASSERT_TRUE(into);
    EXPECT_NEAR(into->t, 0.1, 1e-12);
    EXPECT_GT(into->normal.x, 0);  // out of the material, into the hole
}

TEST(Prism, GrazingWallsAndCapEdgesStayFinite) {
    Geometry g(scene_of({make(square_with_hole())}));
    // Along the wall z = -0.5 at mid-height: in the wall's plane, nothing NaN.
    for (double z : {-0.5, std::nextafter(-0.5, 0.0), std::nextafter(-0.5, -1.0)}) {
        Hit h;
        if (g.intersect(ray({-2, 0.5, z}, {1, 0, 0}), 1e-4, 1e30, h)) {
            EXPECT_TRUE(std::isfinite(h.t) && finite(h.normal)) << z;
        }
    }
    // Through the cap edge (x = 0.5, y = 1) at 45 degrees: the corner is hit at t = sqrt 2.
    auto edge = trace(g, ray({1.5, 2, 0.35}, {-1, -1, 0}));
    ASSERT_TRUE(edge);
    EXPECT_NEAR(edge->t, std::sqrt(2.0), 1e-9);
    // In the cap's plane (|D.y| = 0): the walls are hit, the caps are not tested.
    auto in_cap = trace(g, ray({-2, 1, 0.35}, {1, 0, 0}));
    ASSERT_TRUE(in_cap);
    EXPECT_NEAR(in_cap->t, 1.5, 1e-12);
    EXPECT_FALSE(trace(g, ray({-2, 1 + 1e-9, 0.35}, {1, 0, 0})));
}

TEST(Prism, InsideIsHalfOpenInHeightAndEvenOdd) {
    const auto o = make(square_with_hole());
    EXPECT_TRUE(Geometry::inside(*o, {0.35, 0, 0}));    // on the base: in
    EXPECT_FALSE(Geometry::inside(*o, {0.35, 1, 0}));   // on the cap: out (POV's [H1, H2))
    EXPECT_FALSE(Geometry::inside(*o, {0, 0.5, 0}));    // in the hole
    EXPECT_TRUE(Geometry::inside(*o, {0.35, 0.5, 0}));
    scene::Prism open = square_with_hole();
    open.open = true;
    EXPECT_TRUE(Geometry::inside(*make(open), {0.35, 0.5, 0}));  // open keeps its inside
    Geometry g(scene_of({make(open)}));
    EXPECT_FALSE(trace(g, ray({0.3, 3, 0.1}, {0, -1, 0})));  // and has no caps
}

TEST(Prism, ConicSweepIsAConeFromTheOrigin) {
    scene::Prism p;
    p.conic = true;
    p.height1 = 0.5;
    p.height2 = 1;
    p.points = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}};
    Geometry g(scene_of({make(p)}));
    auto cap = trace(g, ray({0.9, 3, 0}, {0, -1, 0}));
    ASSERT_TRUE(cap);
    EXPECT_NEAR(cap->t, 2, 1e-12);
    // Across at y = 0.75: the wall x = -y.
    auto wall = trace(g, ray({-3, 0.75, 0}, {1, 0, 0}));
    ASSERT_TRUE(wall);
    EXPECT_NEAR(wall->t, 2.25, 1e-12);
    EXPECT_LT(wall->normal.x, 0);
    EXPECT_LT(wall->normal.y, 0);  // the wall leans out as it rises
    // Straight up beside the base's square (half the cap's size): POV-Ray tests no wall for a
    // ray parallel to the sweep, conic too (measured: its view from below shows the cap's
    // underside there), so the cap is what it meets.
    auto up = trace(g, ray({0.7, -3, 0}, {0, 1, 0}));
    ASSERT_TRUE(up);
    EXPECT_NEAR(up->t, 4, 1e-12);
    const auto o = make(p);
    EXPECT_TRUE(Geometry::inside(*o, {0.4, 0.6, 0}));
    EXPECT_FALSE(Geometry::inside(*o, {0.7, 0.6, 0}));
}

TEST(Prism, UnclosedOrNonFiniteIsNeverHit) {
    scene::Prism p = square_with_hole();
    p.spline = scene::SplineKind::Bezier;  // 10 points: no closed groups of four
    p.closed = false;
    EXPECT_FALSE(make_prism(p).valid);
    scene::Prism nan = square_with_hole();
    nan.points[2].x = std::nan("");
    EXPECT_FALSE(make_prism(nan).valid);
    Geometry g(scene_of({make(nan)}));
    EXPECT_FALSE(trace(g, ray({0.3, 3, 0.1}, {0, -1, 0})));
}

// A cylinder of radius 1 from y = 0 to 1 as a linear lathe (no caps).
scene::Lathe tube() {
    scene::Lathe l;
    l.points = {{1, 0}, {1, 1}};
    return l;
}

TEST(Prism, EveryHitAlongARayAsIfTracedAlone) {
    // A prism keeps its last ray's hits for the asks that follow on that ray (CSG retries).
    // Walking every surface from hit to hit must give what each step traced alone gives, and a
    // prism made later, wherever it lies in memory, must not answer with an earlier one's hits.
    auto walk = [](const Geometry& g, const Ray& r) {
        std::vector<double> ts;
        for (double from = 1e-4; ts.size() < 16;) {
            const auto h = trace(g, r, false, from);
            if (!h) break;
            ts.push_back(h->t);
            from = h->t;
        }
        return ts;
    };
    const Ray through = ray({-2, 0.5, 0.1}, {1, 0.05, 0});  // outer wall, hole, hole, outer wall
    std::vector<double> walked;
    {
        Geometry g(scene_of({make(square_with_hole())}));
        walked = walk(g, through);
        ASSERT_EQ(walked.size(), 4u);
        for (size_t k = 0; k < walked.size(); ++k) {
            Geometry fresh(scene_of({make(square_with_hole())}));  // a new prism: nothing kept
            const auto h = trace(fresh, through, false, k == 0 ? 1e-4 : walked[k - 1]);
            ASSERT_TRUE(h);
            EXPECT_EQ(h->t, walked[k]) << k;
        }
    }
    for (int i = 0; i < 20; ++i) {
        // Prisms come and go, each taller than the last, and the same ray falls on each top.
        scene::Prism p = square_with_hole();
        p.height2 = 1 + 0.05 * (i + 1);
        Geometry g(scene_of({make(p)}));
        const auto down = ray({0.3, 3, 0.1}, {0, -1, 0});
        const auto top = trace(g, down);
        ASSERT_TRUE(top);
        EXPECT_NEAR(top->t, 3 - p.height2, 1e-12) << i;
        const auto after = trace(g, down, false, top->t);  // the base, from within
        ASSERT_TRUE(after);
        EXPECT_NEAR(after->t, 3, 1e-12) << i;
    }
}

TEST(Prism, AWalkFromHitToHitUnderAScaleMovesOn) {
    // A prism traces along its normalised object ray (k = t |d|): asked again from the t of a
    // hit, k / |d| rounded back above the ask must not hand the same hit back (the ask after
    // it got that hit over and over: 1024 times a ray in advanced/grenadine's lemon slice).
    const auto o = make(square_with_hole(),
                        from_matrix(glm::rotate(glm::scale(glm::dmat4(1.0), {3.3, 0.7, 1.9}),
                                                0.4, glm::dvec3(0.2, 1, 0.3))));
    Geometry g(scene_of({o}));
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const Ray r = ray({1.5 * u(rng), 1.5 * u(rng), -9}, {0.2 * u(rng), 0.2 * u(rng), 1});
        double from = 1e-4;
        for (int k = 0; k < 12; ++k) {
            const auto h = trace(g, r, false, from);
            if (!h) break;
            ASSERT_GT(h->t, from) << "ray " << i << " step " << k;
            from = h->t;
            ++hits;
            ASSERT_LT(k, 8) << "ray " << i << ": more walls than the outline has";
        }
    }
    EXPECT_GT(hits, 1000);
}

TEST(Lathe, RaysAcrossTheAxisSolveTheCircle) {
    Geometry g(scene_of({make(tube())}));
    auto h = trace(g, ray({-3, 0.5, 0}, {1, 0, 0}));  // |D.y| = 0: S.y(w) = P.y, then k
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 2, 1e-12);
    EXPECT_NEAR(glm::normalize(h->normal).x, -1, 1e-12);
    auto inner = trace(g, ray({0, 0.5, 0}, {1, 0, 0}));
    ASSERT_TRUE(inner);
    EXPECT_NEAR(inner->t, 1, 1e-12);
    // Tangent to the tube (z = 1): a double root, finite if found at all.
    Hit t;
    if (g.intersect(ray({-3, 0.5, 1}, {1, 0, 0}), 1e-4, 1e30, t)) {
        EXPECT_TRUE(std::isfinite(t.t) && finite(t.normal));
    }
    EXPECT_FALSE(trace(g, ray({-3, 0.5, 1 + 1e-9}, {1, 0, 0})));
}

TEST(Lathe, RaysAlongTheAxis) {
    scene::Lathe bulb;  // a Bezier dome closed on the axis: (0,0) out to r 1 and up to (0,1)
    bulb.spline = scene::SplineKind::Bezier;
    bulb.points = {{0, 0}, {1.3, 0}, {1.3, 1}, {0, 1}};
    Geometry g(scene_of({make(bulb)}));
    auto down = trace(g, ray({0, 3, 0}, {0, -1, 0}));
    ASSERT_TRUE(down);
    EXPECT_NEAR(down->t, 2, 1e-9);
    EXPECT_TRUE(finite(down->normal));
    EXPECT_GT(down->normal.y, 0);
    Geometry open(scene_of({make(tube())}));
    EXPECT_FALSE(trace(open, ray({0, 3, 0}, {0, -1, 0})));  // no caps: straight through
    const auto o = make(bulb);
    EXPECT_TRUE(Geometry::inside(*o, {0.2, 0.5, 0.2}));
    EXPECT_FALSE(Geometry::inside(*o, {0.2, 1.2, 0.2}));
}

// r = 1 for all heights: a capped cylinder from y = 0 to 1.
scene::Sor can() {
    scene::Sor s;
    s.points = {{1, -1}, {1, 0}, {1, 1}, {1, 2}};
    return s;
}

TEST(Sor, CapsWallsAndOpen) {
    Geometry g(scene_of({make(can())}));
    auto wall = trace(g, ray({-3, 0.5, 0}, {1, 0, 0}));
    ASSERT_TRUE(wall);
    EXPECT_NEAR(wall->t, 2, 1e-12);
    EXPECT_LT(wall->normal.x, 0);
    auto cap = trace(g, ray({0.2, 3, 0}, {0, -1, 0}));  // along the axis
    ASSERT_TRUE(cap);
    EXPECT_NEAR(cap->t, 2, 1e-12);
    EXPECT_GT(cap->normal.y, 0);
    auto base = trace(g, ray({0.2, -3, 0}, {0, 1, 0}));
    ASSERT_TRUE(base);
    EXPECT_LT(base->normal.y, 0);
    scene::Sor open = can();
    open.open = true;
    Geometry go(scene_of({make(open)}));
    EXPECT_FALSE(trace(go, ray({0.2, 3, 0}, {0, -1, 0})));
    const auto o = make(can());
    EXPECT_TRUE(Geometry::inside(*o, {0.5, 0.5, 0.5}));
    EXPECT_FALSE(Geometry::inside(*o, {0.8, 0.5, 0.8}));
    EXPECT_FALSE(Geometry::inside(*o, {0, 1.1, 0}));
}

TEST(Sor, FarAwayAndThroughTheRim) {
    // The can moved 1e5 away, seen from the origin: the wall distance keeps its precision.
    Geometry g(scene_of({make(can(), translate({1e5, 0, 0}))}));
    auto far = trace(g, ray({0, 0.5, 0}, {1, 0, 0}));
    ASSERT_TRUE(far);
    EXPECT_NEAR(far->t, 1e5 - 1, 1e-6);
    // Through the rim (x = 1, y = 1) at 45 degrees: finite, at the corner.
    Geometry near(scene_of({make(can())}));
    auto rim = trace(near, ray({2, 2, 0}, {-1, -1, 0}));
    ASSERT_TRUE(rim);
    EXPECT_NEAR(rim->t, std::sqrt(2.0), 1e-9);
    EXPECT_TRUE(finite(rim->normal));
}

}  // namespace
}  // namespace lumen::render
