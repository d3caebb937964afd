// CSG operations and modifiers with answers worked out by hand.
#include <cmath>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "render/geometry_test_util.hpp"
#include "render/node.hpp"

namespace lumen::render {
namespace {

using namespace testing;
using scene::CsgOp;

// Two unit spheres overlapping around the origin: centres x = -0.5 and x = +0.5.
std::vector<scene::ObjectPtr> pair() {
    return {make(scene::Sphere{{-0.5, 0, 0}, 1}), make(scene::Sphere{{0.5, 0, 0}, 1})};
}

TEST(Csg, UnionKeepsInnerSurfacesMergeDropsThem) {
    Geometry u(scene_of({csg(CsgOp::Union, pair())}));
    Geometry m(scene_of({csg(CsgOp::Merge, pair())}));
    Ray from_centre = ray({0, 0, 0}, {1, 0, 0});
    auto hu = trace(u, from_centre);
    auto hm = trace(m, from_centre);
    ASSERT_TRUE(hu && hm);
    EXPECT_NEAR(hu->t, 0.5, 1e-12);  // left sphere's far side, inside the right one
    EXPECT_NEAR(hm->t, 1.5, 1e-12);  // merge: only the outer surface
    auto outside = trace(m, ray({-5, 0, 0}, {1, 0, 0}));
    ASSERT_TRUE(outside);
    EXPECT_NEAR(outside->t, 3.5, 1e-12);
}

TEST(Csg, IntersectionIsTheLens) {
    auto lens = csg(CsgOp::Intersection, pair());
    Geometry g(scene_of({lens}));
    auto h = trace(g, ray({-5, 0, 0}, {1, 0, 0}));
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 4.5, 1e-12);  // the right sphere's left side at x = -0.5
    EXPECT_NEAR(h->normal.x, -1, 1e-12);
    EXPECT_FALSE(trace(g, ray({-5, 0.95, 0}, {1, 0, 0})));  // outside the lens' height
    EXPECT_TRUE(Geometry::inside(*lens, {0, 0, 0}));
    EXPECT_FALSE(Geometry::inside(*lens, {1, 0, 0}));
}

TEST(Csg, DifferenceFlipsTheSubtractedSurface) {
    auto cube = make(scene::Box{{-1, -1, -1}, {1, 1, 1}});
    auto hole = make(scene::Sphere{{0, 0, 0}, 0.5});
    auto d = csg(CsgOp::Difference, {cube, hole});
    Geometry g(scene_of({d}));
    auto outer = trace(g, ray({-5, 0, 0}, {1, 0, 0}));
    ASSERT_TRUE(outer);
    EXPECT_NEAR(outer->t, 4, 1e-12);
    auto in_hole = trace(g, ray({0, 0, 0}, {1, 0, 0}));
    ASSERT_TRUE(in_hole);
    EXPECT_NEAR(in_hole->t, 0.5, 1e-12);
    EXPECT_NEAR(in_hole->normal.x, -1, 1e-12);  // faces into the cavity
    EXPECT_EQ(in_hole->object, hole.get());
    EXPECT_TRUE(Geometry::inside(*d, {0.8, 0, 0}));
    EXPECT_FALSE(Geometry::inside(*d, {0.2, 0, 0}));
    // A cylinder drilled all the way through: rays down its axis pass.
    auto drill = make(scene::Cylinder{{0, -2, 0}, {0, 2, 0}, 0.3, false});
    Geometry gd(scene_of({csg(CsgOp::Difference, {cube, drill})}));
    EXPECT_FALSE(trace(gd, ray({0, 5, 0}, {0, -1, 0})));
    auto wall = trace(gd, ray({0.5, 5, 0}, {0, -1, 0}));
    ASSERT_TRUE(wall);
    EXPECT_NEAR(wall->t, 4, 1e-12);
}

TEST(Csg, DifferenceOfSeveral) {
    // difference { A B C } = A minus B minus C.
    auto a = make(scene::Box{{-3, -1, -1}, {3, 1, 1}});
    auto b = make(scene::Sphere{{-2, 0, 0}, 0.5});
    auto c = make(scene::Sphere{{2, 0, 0}, 0.5});
    auto d = csg(CsgOp::Difference, {a, b, c});
    EXPECT_FALSE(Geometry::inside(*d, {-2, 0, 0}));
    EXPECT_FALSE(Geometry::inside(*d, {2, 0, 0}));
    EXPECT_TRUE(Geometry::inside(*d, {0, 0, 0}));
    Geometry g(scene_of({d}));
    auto h = trace(g, ray({2, 0, 0}, {-1, 0, 0}));  // from inside C's hole
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 0.5, 1e-12);
}

TEST(Csg, InverseChildInIntersectionEqualsDifference) {
    auto cube = make(scene::Box{{-1, -1, -1}, {1, 1, 1}});
    auto hole = make(scene::Sphere{{0, 0, 0}, 0.5});
    hole->inverse = true;
    Geometry g(scene_of({csg(CsgOp::Intersection, {cube, hole})}));
    auto h = trace(g, ray({0, 0, 0}, {1, 0, 0}));
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 0.5, 1e-12);
    EXPECT_NEAR(h->normal.x, -1, 1e-12);
    // Inverting the whole CSG flips every normal.
    auto whole = csg(CsgOp::Intersection, pair());
    whole->inverse = true;
    Geometry gi(scene_of({whole}));
    auto hi = trace(gi, ray({-5, 0, 0}, {1, 0, 0}));
    ASSERT_TRUE(hi);
    EXPECT_NEAR(hi->normal.x, 1, 1e-12);
    EXPECT_FALSE(Geometry::inside(*whole, {0, 0, 0}));
}

TEST(Csg, AnInvertedUnionLosesItsInnerSurfaces) {
    // POV-Ray inverts a union into the intersection of its inverted members: cut out of a
    // box, the two overlapping spheres leave one hole with no wall inside it.
    auto cube = make(scene::Box{{-3, -3, -3}, {3, 3, 3}});
    auto holes = csg(CsgOp::Union, pair());
    holes->inverse = true;
    Geometry g(scene_of({csg(CsgOp::Intersection, {cube, holes})}));
    auto h = trace(g, ray({0, 0, 0}, {1, 0, 0}));
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 1.5, 1e-12);  // the right sphere's far side, not the left one's at 0.5
    // At the top level too.
    auto top = csg(CsgOp::Union, pair());
    top->inverse = true;
    Geometry gt(scene_of({top}));
    auto ht = trace(gt, ray({0, 0, 0}, {1, 0, 0}));
    ASSERT_TRUE(ht);
    EXPECT_NEAR(ht->t, 1.5, 1e-12);
}

TEST(Csg, ClippedByLeavesAnOpenShell) {
    auto s = make(scene::Sphere{{0, 0, 0}, 1});
    s->clipped_by = {make(scene::Plane{{0, 1, 0}, 0})};  // keep y < 0
    Geometry g(scene_of({s}));
    auto down = trace(g, ray({0, 5, 0}, {0, -1, 0}));
    ASSERT_TRUE(down);
    EXPECT_NEAR(down->t, 6, 1e-12);  // through the open top to the bottom inside
    EXPECT_NEAR(down->normal.y, -1, 1e-12);
    EXPECT_FALSE(trace(g, ray({-5, 0.5, 0}, {1, 0, 0})));
    auto low = trace(g, ray({-5, -0.5, 0}, {1, 0, 0}));
    ASSERT_TRUE(low);
    EXPECT_NEAR(low->t, 5 - std::sqrt(0.75), 1e-12);
    EXPECT_FALSE(Geometry::inside(*s, {0, 0.5, 0}));
    EXPECT_TRUE(Geometry::inside(*s, {0, -0.5, 0}));
}

TEST(Csg, ClippedUnionPushesTheClipToChildren) {
    auto u = csg(CsgOp::Union, pair());
    u->clipped_by = {make(scene::Box{{-5, -5, -5}, {0, 5, 5}})};  // keep x < 0
    Geometry g(scene_of({u}));
    auto h = trace(g, ray({5, 0, 0}, {-1, 0, 0}));
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 5.5, 1e-12);  // right sphere's far side at x = -0.5
}

TEST(Csg, ClipsOfCsgChildrenAreInWorldSpace) {
    // The interpreter keeps clipped_by complete in world space, also on CSG children.
    auto s = make(scene::Sphere{{0, 0, 0}, 1});
    s->clipped_by = {make(scene::Box{{4, -2, -2}, {6, 0, 2}})};  // lower half, world
    for (auto op : {CsgOp::Union, CsgOp::Merge}) {
        auto parent = csg(op, {s, make(scene::Sphere{{0, 0, 20}, 1})});
        parent->transform = translate({5, 0, 0});
        Geometry g(scene_of({parent}));
        auto h = trace(g, ray({5, 5, 0}, {0, -1, 0}));
        ASSERT_TRUE(h);
        EXPECT_NEAR(h->t, 6, 1e-12);
        EXPECT_TRUE(Geometry::inside(*parent, {5, -0.5, 0}));
        EXPECT_FALSE(Geometry::inside(*parent, {5, 0.5, 0}));
    }
}

TEST(Csg, BoundedBySkipsRaysMissingTheBound) {
    auto s = csg(CsgOp::Union, {make(scene::Sphere{{0, 0, 0}, 1})});
    s->bounded_by = {make(scene::Box{{-0.1, -0.1, -0.1}, {0.1, 0.1, 0.1}})};
    Geometry g(scene_of({s}));
    EXPECT_FALSE(trace(g, ray({-5, 0.5, 0}, {1, 0, 0})));
    auto h = trace(g, ray({-5, 0, 0}, {1, 0, 0}));
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 4, 1e-12);
}

// Several bounding objects bound by their intersection: a ray must meet (or start in) each
// (POV-Ray: a union bounded by two crossed slabs shows only where both are).
TEST(Csg, BoundedByNeedsEveryBound) {
    auto s = csg(CsgOp::Union, {make(scene::Sphere{{0, 0, 0}, 1})});
    s->bounded_by = {make(scene::Box{{-2, -0.1, -2}, {2, 0.1, 2}}),
                     make(scene::Box{{-0.1, -2, -2}, {0.1, 2, 2}})};
    Geometry g(scene_of({s}));
    EXPECT_FALSE(trace(g, ray({-5, 0.5, 0}, {1, 0, 0})));  // meets the second slab only
    EXPECT_FALSE(trace(g, ray({0.5, 0, -5}, {0, 0, 1})));  // the first only
    auto h = trace(g, ray({0.05, 0, -5}, {0, 0, 1}));      // both
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 5 - std::sqrt(1 - 0.05 * 0.05), 1e-12);
}

TEST(Csg, NestedWithTransforms) {
    // union { difference { box, sphere } translate x*10 } rotate y*90: cube centre at (0,0,-10).
    auto d = csg(CsgOp::Difference, {make(scene::Box{{-1, -1, -1}, {1, 1, 1}}),
                                     make(scene::Sphere{{0, 0, 0}, 0.5})});
    d->transform = translate({10, 0, 0});
    auto u = csg(CsgOp::Union, {d});
    u->transform = rotate(90, {0, 1, 0});
    Geometry g(scene_of({u}));
    auto h = trace(g, ray({0, 0, -10}, {1, 0, 0}));  // from the cavity centre
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 0.5, 1e-9);
    EXPECT_NEAR(h->normal.x, -1, 1e-9);
    EXPECT_TRUE(Geometry::inside(*u, {0.8, 0, -10}));
}

// Walks each ray from hit to hit through `obj` (the only object of `g`): the point test's
// answer must flip at every hit and stay the same at sampled points between them, so a hit
// list that drops a member's hit, keeps a rejected one or repeats one fails. Returns the
// number of surfaces met.
std::string describe(const Ray& r) {
    std::ostringstream s;
    s.precision(17);
    s << "from " << r.origin.x << ' ' << r.origin.y << ' ' << r.origin.z << " along " << r.dir.x
      << ' ' << r.dir.y << ' ' << r.dir.z;
    return s.str();
}

int expect_surfaces_where_inside_changes(const Geometry& g, const scene::Object& obj,
                                         const std::vector<Ray>& rays, double far) {
    int surfaces = 0;
    for (size_t i = 0; i < rays.size(); ++i) {
        const Ray& r = rays[i];
        const auto in = [&](double t) { return Geometry::inside(obj, r.at(t)); };
        std::vector<double> ts{1e-4};
        while (ts.size() < 32) {
            const auto h = trace(g, r, false, ts.back());
            if (!h) break;
            EXPECT_GT(h->t, ts.back()) << "ray " << i;
            if (!(h->t > ts.back())) return surfaces;
            ts.push_back(h->t);
        }
        surfaces += int(ts.size()) - 1;
        ts.push_back(far);
        // Between hits the answer is the same throughout, and it flips across each odd number
        // of hits, except across hits a few ulps apart (a ray passing near an edge).
        int crossed = 0;
        bool cluster = false;  // the point test cannot tell in which order those are met
        std::optional<bool> before;
        for (size_t k = 0; k + 1 < ts.size(); ++k) {
            if (k > 0) ++crossed;
            if (!(ts[k + 1] - ts[k] > 1e-9)) {
                cluster = true;
                continue;
            }
            const bool state = in(0.5 * (ts[k] + ts[k + 1]));
            for (int s = 1; s < 8; ++s)
                if (in(ts[k] + (ts[k + 1] - ts[k]) * s / 8.0) != state) {
                    ADD_FAILURE() << "ray " << i << ": a surface missed between " << ts[k]
                                  << " and " << ts[k + 1] << " (" << describe(r) << ")";
                    return surfaces;
                }
            if (before && !cluster && (state != *before) != (crossed % 2 == 1)) {
                ADD_FAILURE() << "ray " << i << ": no change of inside across " << crossed
                              << " hit(s) up to " << ts[k] << " (" << describe(r) << ")";
                return surfaces;
            }
            before = state;
            crossed = 0;
            cluster = false;
        }
    }
    return surfaces;
}

TEST(Csg, EveryHitIsWhereInsideChangesAndNowhereElse) {
    // Merges, intersections and differences of transformed shapes (a prism and a torus among
    // them: shapes that work in their own units), nested three deep, have a surface exactly
    // where the point test's answer changes.
    scene::Prism wedge;
    wedge.points = {{0, 0}, {1, -0.3}, {1, 0.3}, {0, 0}};
    auto shell = csg(CsgOp::Difference, {make(scene::Box{{-1, -1, -1}, {1, 1, 1}}),
                                         make(scene::Sphere{{0, 0, 0}, 1.2})});
    auto ring = csg(CsgOp::Intersection,
                    {make(scene::Torus{1.1, 0.35, false}, scale({1, 1.6, 1})),
                     make(scene::Cylinder{{0, -2, 0}, {0, 2, 0}, 1.3, false}),
                     make(wedge, scale({1.6, 0.8, 1.6}).then(rotate(30, {1, 0.2, 0})))});
    auto cut = csg(CsgOp::Difference,
                   {csg(CsgOp::Merge, {shell, ring}),
                    make(scene::Box{{-0.3, -2, -0.3}, {0.3, 2, 0.3}}, rotate(25, {0, 1, 1}))});
    Geometry g(scene_of({cut}));
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<Ray> rays;
    for (int i = 0; i < 3000; ++i)
        rays.push_back(ray({1.4 * u(rng), 1.4 * u(rng), -5}, {0.3 * u(rng), 0.3 * u(rng), 1}));
    EXPECT_GT(expect_surfaces_where_inside_changes(g, *cut, rays, 12.0), 2000);
}

TEST(Csg, HalfSpaceMembersNarrowTheOthersAndKeepEverySurface) {
    // chess2.pov's rook: its battlements are unions of planes (merges here: a union keeps
    // the surfaces inside it, where the point test does not change) and its body a cylinder
    // with a bore between two planes. A member's hits are sought only where the ray is inside
    // every other member's box, a plane's half-space included; rays from outside, from the
    // bore and from within the walls, some along the axes, meet every surface.
    auto plane = [](glm::dvec3 n, double d) { return make(scene::Plane{n, d}); };
    auto bore = make(scene::Quadric{{1, 0, 1}, {0, 0, 0}, {0, 0, 0}, -1.44});
    bore->inverse = true;
    auto rook = csg(CsgOp::Intersection,
                    {csg(CsgOp::Merge, {plane({1, 0, 0}, -0.5), plane({-1, 0, 0}, -0.5),
                                        plane({0, 1, 0}, 9)}),
                     csg(CsgOp::Merge, {plane({0, 0, 1}, -0.5), plane({0, 0, -1}, -0.5),
                                        plane({0, 1, 0}, 9)}),
                     plane({0, 1, 0}, 10),
                     make(scene::Quadric{{1, 0, 1}, {0, 0, 0}, {0, 0, 0}, -4}), bore,
                     plane({0, -1, 0}, -8)});
    Geometry g(scene_of({rook}));
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<Ray> rays;
    for (int i = 0; i < 3000; ++i) {
        const glm::dvec3 from = i % 3 == 0 ? glm::dvec3(6 * u(rng), 9 + 4 * u(rng), -8)
                                           : glm::dvec3(2 * u(rng), 9 + 1.5 * u(rng), 2 * u(rng));
        glm::dvec3 dir{u(rng), u(rng), u(rng)};
        if (i % 3 == 0) dir.z = 1;
        if (i % 7 == 0) dir = glm::dvec3(0, 0, 0), dir[i % 3] = u(rng) < 0 ? -1 : 1;
        rays.push_back(ray(from, dir));
    }
    EXPECT_GT(expect_surfaces_where_inside_changes(g, *rook, rays, 30.0), 1500);
}

TEST(Csg, RaysFromInsideSubtractedBoxesMeetEverySurface) {
    // A wall block with rooms cut out of it (radiosity/radiosity_36.pov's courtyard): a ray
    // that starts in a cut-out room skips the other members' hits up to where it leaves the
    // room, through rooms that touch, overlap or nest and a cut with a round arch. Rays start
    // anywhere in the block, rooms included, in every direction, some along a face.
    auto arch = csg(CsgOp::Intersection,
                    {make(scene::Cylinder{{0, 0.3, -6}, {0, 0.3, 6}, 1.5, false}),
                     make(scene::Box{{-3, 0.3, -7}, {3, 3, 7}})});
    auto block = csg(CsgOp::Difference,
                     {make(scene::Box{{-5, -1, -5}, {5, 3, 5}}),
                      make(scene::Box{{-4, 0, -4}, {4, 2.5, 4}}),       // the room
                      make(scene::Box{{3.8, 0.3, -1}, {4.6, 2, 1}}),    // a niche in its wall
                      make(scene::Box{{4.3, 0.5, -0.5}, {6, 1.5, 0.5}}), // overlapping that, out
                      make(scene::Box{{-2, 0.5, -2}, {2, 4, 2}}),       // out through the top
                      make(scene::Box{{-1, 1, -1}, {1, 2, 1}}),         // nested in both
                      arch,
                      make(scene::Box{{-4.5, 0.2, 4.2}, {4.5, 2, 4.6}}, rotate(10, {0, 1, 0}))});
    Geometry g(scene_of({block}));
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<Ray> rays;
    for (int i = 0; i < 3000; ++i) {
        glm::dvec3 o{5.5 * u(rng), 1 + 2.5 * u(rng), 5.5 * u(rng)};
        glm::dvec3 d{u(rng), u(rng), u(rng)};
        if (i % 10 == 0) o.y = 0, d.y = 0;     // along the room's floor
        if (i % 10 == 1) d.x = 0, d.z = 0;     // straight up or down
        if (glm::length(d) < 1e-3) d = {0, 1, 0};
        rays.push_back(ray(o, d));
    }
    EXPECT_GT(expect_surfaces_where_inside_changes(g, *block, rays, 40.0), 3000);
}

TEST(Csg, RetriesAlongARayGetTheAnswersOfFreshTraces) {
    // Nested CSG (a merge of differences, one inside an intersection with a union of
    // several) asks its members again and again along one ray; the answers a thread remembers
    // must be those a fresh trace gives. Every surface along 300 random rays, walked from hit to
    // hit on this thread, against each step traced alone on a new thread.
    std::vector<scene::ObjectPtr> spheres;
    for (int i = 0; i < 6; ++i)
        spheres.push_back(make(scene::Sphere{{-1.2 + 0.5 * i, 0.1 * i, 0}, 0.3}));
    auto shells = csg(CsgOp::Union, spheres);
    auto ring = csg(CsgOp::Difference, {make(scene::Sphere{{0, 0, 0}, 1.5}),
                                        make(scene::Sphere{{0, 0, 0}, 1.3})});
    auto cut = csg(CsgOp::Intersection, {ring, make(scene::Box{{-2, -0.4, -2}, {2, 0.4, 2}})});
    auto both = csg(CsgOp::Merge, {cut, csg(CsgOp::Difference, {make(scene::Box{{-1.6, -0.2, -0.5}, {1.6, 0.2, 0.5}}), shells})});
    Geometry g(scene_of({both}));
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    int surfaces = 0;
    for (int i = 0; i < 300; ++i) {
        const Ray r = ray({1.5 * u(rng), 0.3 * u(rng), -4}, {0.2 * u(rng), 0.05 * u(rng), 1});
        std::vector<double> walked, fresh;
        for (double from = 1e-4;;) {
            const auto h = trace(g, r, false, from);
            if (!h) break;
            walked.push_back(h->t);
            from = h->t;
            if (walked.size() > 64) break;
        }
        std::thread([&] {
            double from = 1e-4;
            for (size_t k = 0; k <= walked.size(); ++k) {
                // A different ray between the steps, so nothing is remembered for this one.
                trace(g, ray({0, 0, -4}, {0.01 * double(k), 0, 1}));
                const auto h = trace(g, r, false, from);
                if (!h) break;
                fresh.push_back(h->t);
                from = h->t;
            }
        }).join();
        ASSERT_EQ(walked, fresh) << "ray " << i;
        surfaces += int(walked.size());
    }
    EXPECT_GT(surfaces, 300);
}

// A quarter of a long rotated ellipsoid cut out by planes along its own axes (abyss.pov's
// submarine hull): the intersection is boxed as that quarter in its own frame, then rotated,
// as POV-Ray boxes it; in world space the rotated planes bound nothing. The box culls rays
// that meet only the rest of the ellipsoid's box, and the hits are the same.
TEST(Csg, ARotatedIntersectionIsBoxedInItsOwnFrame) {
    auto hull = make(scene::Sphere{{0, 0, 0}, 1});
    hull->transform = scale({1, 1, 10});
    auto cut = [](glm::dvec3 n, bool inverse) {
        auto p = make(scene::Plane{n, 0});
        p->inverse = inverse;
        return p;
    };
    // Keeps y > 0, z > 0 and x < 0.
    auto quarter = csg(CsgOp::Difference, {hull, cut({0, 1, 0}, false), cut({0, 0, 1}, false),
                                           cut({1, 0, 0}, true)});
    quarter->transform = rotate(-15, {0, 1, 0});
    NodeStore store;
    const Node& node = store.nodes[compile_object(store, *quarter, NodeContext{})];
    ASSERT_TRUE(node.surface.finite());
    // The rotated quarter: x in [-(cos 15 + 10 sin 15), 0] and z in [-sin 15, 10 cos 15],
    // where the whole ellipsoid spans x and z in +-(cos 15 + 10 sin 15), +-(sin 15 + 10 cos 15).
    const double c = std::cos(glm::radians(15.0)), s = std::sin(glm::radians(15.0));
    EXPECT_NEAR(node.surface.lo.x, -(c + 10 * s), 1e-6);
    EXPECT_NEAR(node.surface.hi.x, 0, 1e-6);
    EXPECT_NEAR(node.surface.lo.z, -s, 1e-6);
    EXPECT_NEAR(node.surface.hi.z, 10 * c, 1e-6);
    EXPECT_NEAR(node.surface.lo.y, 0, 1e-6);
    EXPECT_NEAR(node.surface.hi.y, 1, 1e-6);
    Geometry g(scene_of({quarter}));
    // Every crossing found where the point test says the inside changes.
    std::mt19937 rng(15);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<Ray> rays;
    for (int i = 0; i < 400; ++i)
        rays.push_back(ray({2 * u(rng) - 1.5, 0.7 * u(rng) + 0.5, 12 * u(rng) - 20},
                           {0.1 * u(rng), 0.03 * u(rng), 1}));
    EXPECT_GT(expect_surfaces_where_inside_changes(g, *quarter, rays, 60), 100);
}

}  // namespace
}  // namespace lumen::render
