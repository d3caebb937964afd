// blob: agreement with the closed forms of single components, rays along a cylinder's axis,
// rays from inside, tangent and far-away rays, degenerate components, shared boundaries.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "render/geometry_test_util.hpp"
#include "render/shapes.hpp"

namespace lumen::render {
namespace {

using namespace testing;

scene::Blob::Component sphere(glm::dvec3 c, double r, double s) {
    scene::Blob::Component k;
    k.a = k.b = c;
    k.radius = r;
    k.strength = s;
    return k;
}
scene::Blob::Component cylinder(glm::dvec3 a, glm::dvec3 b, double r, double s) {
    scene::Blob::Component k = sphere(a, r, s);
    k.cylinder = true;
    k.b = b;
    return k;
}
scene::Blob blob(double threshold, std::vector<scene::Blob::Component> cs) {
    scene::Blob b;
    b.threshold = threshold;
    b.components = std::move(cs);
    return b;
}
// Where S (1 - d^2/R^2)^2 = T.
double surface_radius(double R, double S, double T) { return R * std::sqrt(1 - std::sqrt(T / S)); }

TEST(Blob, OneSphereComponentIsASphere) {
    const double r = surface_radius(1.5, 2, 0.7);
    Geometry b(scene_of({make(blob(0.7, {sphere({0.3, 0, 0}, 1.5, 2)}))}));
    Geometry s(scene_of({make(scene::Sphere{{0.3, 0, 0}, r})}));
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    int hits = 0;
    for (int i = 0; i < 400; ++i) {
        glm::dvec3 o{u(rng) * 3, u(rng) * 3, -4}, target{u(rng), u(rng), u(rng)};
        const Ray rr = ray(o, target - o);
        auto a = trace(b, rr), c = trace(s, rr);
        // Tangent rays may go either way: only rays clearly in or out are compared.
        const double miss = glm::length(glm::cross(glm::dvec3{0.3, 0, 0} - o, rr.dir));
        if (std::fabs(miss - r) < 1e-6) continue;
        ASSERT_EQ(bool(a), bool(c)) << i;
        if (!a) continue;
        ++hits;
        EXPECT_NEAR(a->t, c->t, 1e-9) << i;
        EXPECT_NEAR(glm::dot(a->normal, c->normal), 1, 1e-9) << i;
    }
    EXPECT_GT(hits, 100);
}

TEST(Blob, CylinderComponentIsACapsuleEvenAlongItsAxis) {
    const double r = surface_radius(1, 1, 0.5);
    Geometry g(scene_of({make(blob(0.5, {cylinder({0, -1, 0}, {0, 1, 0}, 1, 1)}))}));
    // Along the axis (the cylinder's quadratic vanishes): the caps' apexes.
    for (double x : {0.0, 0.2, -0.3}) {
        auto down = trace(g, ray({x, 5, 0}, {0, -1, 0}));
        ASSERT_TRUE(down) << x;
        EXPECT_NEAR(down->point.y, 1 + std::sqrt(r * r - x * x), 1e-9);
        EXPECT_NEAR(down->normal.y, std::sqrt(r * r - x * x) / r, 1e-9);
        auto up = trace(g, ray({x, -5, 0}, {0, 1, 0}));
        ASSERT_TRUE(up);
        EXPECT_NEAR(up->point.y, -1 - std::sqrt(r * r - x * x), 1e-9);
    }
    EXPECT_FALSE(trace(g, ray({r + 1e-3, 5, 0}, {0, -1, 0})));
    // Across it: the side at the surface radius, normal straight out.
    auto side = trace(g, ray({-5, 0.4, 0}, {1, 0, 0}));
    ASSERT_TRUE(side);
    EXPECT_NEAR(side->point.x, -r, 1e-9);
    EXPECT_NEAR(side->normal.x, -1, 1e-9);
}

TEST(Blob, RaysFromInsideFindTheWallBeyondTheMinimumDepth) {
    Geometry g(scene_of({make(blob(0.5, {sphere({0, 0, 0}, 2, 1), sphere({1, 0, 0}, 1, -0.3)}))}));
    const double r = surface_radius(2, 1, 0.5);
    auto h = trace(g, ray({0, 0, 0}, {0, 1, 0}));
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, r, 1e-9);
    // A ray leaving the surface goes on to the far side, never back to t ~ 0.
    auto out = trace(g, ray(h->point, {0, -1, 0}));
    ASSERT_TRUE(out);
    EXPECT_NEAR(out->t, 2 * r, 1e-9);
    EXPECT_FALSE(trace(g, ray(h->point, {0, 1, 0})));
}

TEST(Blob, TangentGrazingAndFarRaysStayFinite) {
    const double r = surface_radius(1, 1, 0.5);
    Geometry g(scene_of({make(blob(0.5, {sphere({0, 0, 0}, 1, 1), cylinder({0, 0, 0}, {2, 0, 0}, 0.5, 1)}))}));
    for (double off : {r - 1e-12, r, r + 1e-12, r - 1e-7}) {
        auto h = trace(g, ray({-5, off, -3}, {0, 0, 1}));
        if (h) {
            EXPECT_TRUE(std::isfinite(h->t) && std::isfinite(glm::dot(h->normal, h->normal)));
            EXPECT_NEAR(glm::length(h->normal), 1, 1e-9);
        }
    }
    Geometry far(scene_of({make(blob(0.5, {sphere({0, 0, 0}, 1, 1)}), translate({0, 0, 1e5}))}));
    auto h = trace(far, ray({0, 0, 0}, {0, 0, 1}));
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 1e5 - r, 1e-6);
}

TEST(Blob, DegenerateComponents) {
    // A zero radius has no density (POV-Ray draws nothing of it); a non-finite value makes
    // the blob never hit rather than NaN.
    Geometry zero(scene_of({make(blob(0.5, {sphere({0, 0, 0}, 0, 1)}))}));
    EXPECT_FALSE(trace(zero, ray({0, 0, -5}, {0, 0, 1})));
    Geometry bad(scene_of({make(blob(0.5, {sphere({0, 0, 0}, 1, std::nan(""))}))}));
    EXPECT_FALSE(trace(bad, ray({0, 0, -5}, {0, 0, 1})));
    Geometry inf(scene_of({make(blob(0.5, {sphere({0, 0, 0}, 1, 1), sphere({1e308, 0, 0}, 1e308, 1)}))}));
    EXPECT_FALSE(trace(inf, ray({0, 0, -5}, {0, 0, 1})));
}

TEST(Blob, EndPlanesCountForBothParts) {
    // Level with a cylinder's end, the open cylinder and the end's hemisphere both add their
    // density (POV-Ray's inclusive bounds): a point there is inside where neither alone is.
    const BlobShape s = make_blob(blob(0.4, {cylinder({0, 0, 0}, {0, 1, 0}, 1, 1)}));
    const double d = 0.7;  // (1 - 0.49)^2 = 0.26: below 0.4 once, above it twice
    EXPECT_TRUE(inside(s, {d, 1, 0}));
    EXPECT_TRUE(inside(s, {d, 0, 0}));
    EXPECT_FALSE(inside(s, {d, 1 + 1e-9, 0}));
    EXPECT_FALSE(inside(s, {d, 0.5, 0}));
    EXPECT_NEAR(blob_density(s, {d, 1, 0}), 2 * 0.2601, 1e-12);
}

TEST(Blob, TextureWeightsAreTheComponentsDensities) {
    scene::Blob b = blob(0.5, {sphere({-1, 0, 0}, 2, 1), sphere({1, 0, 0}, 2, 3), sphere({9, 0, 0}, 1, 1)});
    b.components[1].texture = some_texture();
    const BlobShape s = make_blob(b);
    EXPECT_TRUE(s.textured);
    double w[3] = {0, 0, 0};
    for_each_blob_density(s, {0, 0, 0}, [&](int c, double d) { w[c] += d; });
    EXPECT_NEAR(w[0], 1 * 0.75 * 0.75, 1e-12);
    EXPECT_NEAR(w[1], 3 * 0.75 * 0.75, 1e-12);
    EXPECT_EQ(w[2], 0);
}

}  // namespace
}  // namespace lumen::render

namespace lumen::render {
namespace {

// A long cylinder is boxed piece by piece for the tree: its density at a point still counts
// once (against the sum over every element), and rays along and across it find the surface
// a blob with the cylinder boxed whole would.
TEST(Blob, LongCylindersBoxedInPiecesCountOnce) {
    const scene::Blob b = blob(0.5, {cylinder({-6, 0.1, 0}, {6, -0.2, 0.3}, 0.5, 1),
                                     sphere({0, 0.8, 0}, 1, 1), sphere({3, 0, 0.2}, 0.7, -0.5)});
    const BlobShape s = make_blob(b);
    ASSERT_GT(s.box_element.size(), s.elements.size());  // the cylinder is in pieces
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int i = 0; i < 2000; ++i) {
        const glm::dvec3 p{u(rng) * 7, u(rng), u(rng)};
        double sum = 0;
        for (const BlobElement& e : s.elements) sum += blob_element_density(s, e, p);
        ASSERT_NEAR(blob_density(s, p), sum, 1e-12) << i;
    }
    // The capsule's surface radius where the sphere and the negative one are far away.
    const double r = surface_radius(0.5, 1, 0.5);
    const auto hit = trace(Geometry(scene_of({make(b)})), ray({-4.5, 5, 0}, {0, -1, 0}));
    ASSERT_TRUE(hit);
    const double axis_y = 0.1 - 0.3 / 12 * 1.5;  // the axis's height at x = -4.5
    const double along_z = 0.3 / 12 * 1.5;
    EXPECT_NEAR(hit->t, 5 - axis_y - std::sqrt(r * r - along_z * along_z), 1e-3);
}

// The density is at most 0 outside the components of positive strength, so the blob lies
// within their boxes: abyss.pov's hull carves its portholes with long negative cylinders that
// reach far beyond it. Not for a threshold so low that the inside test passes at density 0.
TEST(Blob, BoxedByItsPositiveComponentsAlone) {
    const BlobShape s = make_blob(blob(0.6, {sphere({0, 0, 0}, 1, 1),
                                             cylinder({0, 0, -6}, {0, 0, 3}, 0.2, -1)}));
    EXPECT_NEAR(bounds(s).lo.z, -1, 1e-9);
    EXPECT_NEAR(bounds(s).hi.z, 1, 1e-9);
    EXPECT_LE(s.box.lo.z, -6.2);  // the solver's span still holds the cylinder
    EXPECT_FALSE(inside(s, {0, 0, -4}));
    const BlobShape low = make_blob(blob(1e-7, {sphere({0, 0, 0}, 1, 1),
                                                cylinder({0, 0, -6}, {0, 0, 3}, 0.2, -1)}));
    EXPECT_TRUE(inside(low, {0, 5, 0}));
    EXPECT_LE(solid_bounds(low).lo.z, -6.2);
}

}  // namespace
}  // namespace lumen::render
