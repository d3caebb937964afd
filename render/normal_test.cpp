// Normal perturbation: its geometry (unit length, the tilt against the pattern's slope, the
// transforms, no_bump_scale), slope_map, normal_map and average, the dedicated forms, and the
// degenerate cases that must not reach a pixel as NaN. Pixel-exact agreement with povray is
// checked by the probe scenes of tests/normals (the differential suite).
#include "render/normal.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "noise/noise.hpp"
#include "render/patterns/normal_forms.hpp"

namespace lumen::render {
namespace {

const glm::dvec3 kFacing{0, 0, -1};  // a plane z = c seen from -z

scene::Normal normal_of(scene::PatternKind kind, double amount = 0.5) {
    scene::Normal n;
    n.pattern.kind = std::move(kind);
    n.amount = amount;
    return n;
}

scene::NormalPtr shared(scene::Normal n) { return std::make_shared<const scene::Normal>(std::move(n)); }

scene::Transform scaled(const glm::dvec3& s) {
    return {glm::scale(glm::dmat4(1.0), s), glm::scale(glm::dmat4(1.0), 1.0 / s)};
}
scene::Transform rotated_z(double degrees) {
    const glm::dmat4 m = glm::rotate(glm::dmat4(1.0), glm::radians(degrees), {0, 0, 1});
    return {m, glm::inverse(m)};
}

void expect_near(const glm::dvec3& a, const glm::dvec3& b, double eps = 1e-12) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// gradient x rises along x: the normal leans towards -x, to first order by 2/15 of the amount
// times the slope (four samples of the value a tetrahedron around the point).
TEST(Normal, LeansAgainstTheSlopeOfTheValue) {
    const scene::Normal n = normal_of(scene::pattern::Gradient{{1, 0, 0}}, 1.5);
    const glm::dvec3 p{0.3, 0.2, 0.37};
    const glm::dvec3 out = perturbed_normal(n, kFacing, p);
    EXPECT_NEAR(glm::length(out), 1.0, 1e-15);
    expect_near(out, glm::normalize(kFacing - (2.0 / 15) * 1.5 * glm::dvec3(1, 0, 0)), 1e-8);
}

TEST(Normal, AccuracyDoesNotChangeALinearSlope) {
    scene::Normal n = normal_of(scene::pattern::Gradient{{0, 1, 0}}, 2);
    const glm::dvec3 p{0.1, 0.4, 0.37};
    const glm::dvec3 fine = perturbed_normal(n, kFacing, p);
    n.accuracy = 0.1;
    expect_near(perturbed_normal(n, kFacing, p), fine, 1e-7);
}

// POV brings the normal into pattern space and back: a uniform scale cancels, a non-uniform
// one tilts the perturbation, no_bump_scale makes a smaller pattern tilt more.
TEST(Normal, TransformsAndNoBumpScale) {
    scene::Normal n = normal_of(scene::pattern::Gradient{{1, 0, 0}}, 1);
    const glm::dvec3 p{0.13, 0.2, 0.37};
    const glm::dvec3 plain = perturbed_normal(n, kFacing, p);
    n.pattern.steps.add_transform(scaled(glm::dvec3(0.5)));
    expect_near(perturbed_normal(n, kFacing, p), plain, 1e-9);

    n.no_bump_scale = true;  // normalize(N + D/s): twice the tilt at half the size
    expect_near(perturbed_normal(n, kFacing, p),
                glm::normalize(kFacing - (2.0 / 15) * 2.0 * glm::dvec3(1, 0, 0)), 1e-8);

    scene::Normal skew = normal_of(scene::pattern::Gradient{glm::normalize(glm::dvec3(1, 1, 0))}, 1);
    skew.pattern.steps.add_transform(scaled({1, 4, 1}));
    // The slope along the stretched y is a quarter of the slope along x.
    const glm::dvec3 out = perturbed_normal(skew, kFacing, p);
    EXPECT_NEAR(glm::length(out), 1.0, 1e-15);
    EXPECT_LT(out.x, -0.05);
    EXPECT_NEAR(out.x, 4 * out.y, 1e-8);

    scene::Normal turned = normal_of(scene::pattern::Gradient{{1, 0, 0}}, 1);
    turned.pattern.steps.add_transform(rotated_z(90));  // now rising along +y
    const glm::dvec3 t = perturbed_normal(turned, kFacing, p);
    EXPECT_NEAR(t.x, 0, 1e-8);
    EXPECT_LT(t.y, -0.1);
}

// Whatever the amount, the result is unit length or the raw normal, never NaN: an amount so
// large that the sum overflows, an accuracy of 0 (POV divides by it), and a perturbation that
// cancels the normal exactly.
TEST(Normal, DegenerateCasesFallBackToTheRawNormal) {
    const glm::dvec3 p{0.3, 0.2, 0.37};
    for (double amount : {0.0, 1e6, 1e300, std::numeric_limits<double>::infinity()}) {
        const glm::dvec3 out =
            perturbed_normal(normal_of(scene::pattern::Gradient{{1, 0, 0}}, amount), kFacing, p);
        EXPECT_TRUE(finite(out)) << amount;
        EXPECT_NEAR(glm::length(out), 1.0, 1e-12) << amount;
    }
    scene::Normal zero_accuracy = normal_of(scene::pattern::Gradient{{1, 0, 0}}, 1);
    zero_accuracy.accuracy = 0;
    EXPECT_EQ(perturbed_normal(zero_accuracy, kFacing, p), kFacing);

    // A quilt's perturbation is amount * d * profile / (sqrt 3 / 2): with an amount that
    // makes it -N the sum is zero (or a rounding error's worth of a vector).
    scene::Normal quilt = normal_of(scene::pattern::Quilted{0, 0}, 1);
    quilt.no_bump_scale = true;
    const glm::dvec3 corner{0.5, 0.5, 1.0};  // d = (0, 0, -0.5), profile 0.125
    quilt.amount = 1 / (0.5 * 0.125 / (std::sqrt(3.0) / 2));
    const glm::dvec3 out = perturbed_normal(quilt, {0, 0, 1}, corner);
    EXPECT_TRUE(finite(out));
    EXPECT_NEAR(glm::length(out), 1.0, 1e-12);
}

// Moderate amounts keep the normal on the viewer's side; POV does not turn one that a large
// amount sends past the surface back (tests/normals/grazing.pov matches it pixel for pixel).
TEST(Normal, FacesTheViewerUnlessTheAmountTurnsItPast) {
    const glm::dvec3 p{0.3, 0.2, 0.37};
    const glm::dvec3 mild = perturbed_normal(normal_of(scene::pattern::Gradient{{0, 0, 1}}, 3), kFacing, p);
    EXPECT_LT(mild.z, 0);
    const glm::dvec3 past = perturbed_normal(normal_of(scene::pattern::Gradient{{0, 0, 1}}, -30), kFacing, p);
    EXPECT_GT(past.z, 0);
    EXPECT_NEAR(glm::length(past), 1.0, 1e-12);
}

TEST(Normal, PlainNormalAndZeroAmountKeepTheRawNormal) {
    const glm::dvec3 raw = glm::normalize(glm::dvec3(0.2, -0.3, -1));
    EXPECT_EQ(perturbed_normal(scene::Normal{}, raw, {1, 2, 3}), raw);
    expect_near(perturbed_normal(normal_of(scene::pattern::Gradient{{1, 0, 0}}, 0), raw, {1, 2, 3}),
                raw);
}

TEST(Normal, SlopeMapIsACubicThroughHeightsWithSlopes) {
    const scene::SlopeMap map{{0, {0, 1}}, {0.5, {1, 0}}, {1, {0, -1}}};
    EXPECT_DOUBLE_EQ(slope_height(map, 0), 0);
    EXPECT_DOUBLE_EQ(slope_height(map, 0.5), 1);
    EXPECT_DOUBLE_EQ(slope_height(map, 1), 0);
    EXPECT_DOUBLE_EQ(slope_height(map, -3), 0);   // below the first key: its height
    EXPECT_DOUBLE_EQ(slope_height(map, 7), 0);    // at or above the last: its height
    // Halfway between keys 0 and 0.5: t = 0.5, h0 0, s0 1, h1 1, s1 0 (slopes per unit t).
    EXPECT_DOUBLE_EQ(slope_height(map, 0.25), 0.125 * (1 + 0 - 2) - 0.25 * (2 + 0 - 3) + 0.5);
    // A single entry is a constant height.
    EXPECT_DOUBLE_EQ(slope_height(scene::SlopeMap{{0.5, {0.3, 2}}}, 0.1), 0.3);
    // No map: the value itself.
    EXPECT_DOUBLE_EQ(slope_height(scene::SlopeMap{}, 0.42), 0.42);
}

// A slope_map with a constant height leaves nothing to difference.
TEST(Normal, FlatSlopeMapLeavesTheNormal) {
    scene::Normal n = normal_of(scene::pattern::Gradient{{1, 0, 0}}, 2);
    n.slope_map = {{0, {0.5, 0}}, {1, {0.5, 0}}};
    expect_near(perturbed_normal(n, kFacing, {0.3, 0.2, 0.37}), kFacing, 1e-7);
}

// normal_map: the entries around the value, each evaluated at the parent's pattern-space
// point and blended; at an entry's key that entry alone; the parent's amount does not count.
TEST(Normal, NormalMapBlendsItsEntries) {
    const scene::Normal rise_x = normal_of(scene::pattern::Gradient{{1, 0, 0}}, 1);
    const scene::Normal rise_y = normal_of(scene::pattern::Gradient{{0, 1, 0}}, 1);
    scene::Normal map = normal_of(scene::pattern::Gradient{{0, 0, 1}}, 7);
    map.normal_map = {{0, shared(rise_x)}, {1, shared(rise_y)}};
    const glm::dvec3 at_key{0.3, 0.2, 0};  // value 0
    expect_near(perturbed_normal(map, kFacing, at_key), perturbed_normal(rise_x, kFacing, at_key));
    const glm::dvec3 between{0.3, 0.2, 0.25};
    const glm::dvec3 blended = perturbed_normal(map, kFacing, between);
    const glm::dvec3 want = glm::normalize(0.75 * perturbed_normal(rise_x, kFacing, between) +
                                           0.25 * perturbed_normal(rise_y, kFacing, between));
    expect_near(blended, want);

    // The parent's scale moves its entries (they live in its pattern space).
    scene::Normal scaled_map = map;
    scaled_map.pattern.steps.add_transform(scaled(glm::dvec3(2)));
    scene::Normal scaled_x = rise_x;
    scaled_x.pattern.steps.add_transform(scaled(glm::dvec3(2)));
    const glm::dvec3 q{0.3, 0.2, 0};
    expect_near(perturbed_normal(scaled_map, kFacing, q), perturbed_normal(scaled_x, kFacing, q));
}

TEST(Normal, AverageWeighsTheEntries) {
    const scene::Normal left = normal_of(scene::pattern::Gradient{{1, 0, 0}}, 1);
    const scene::Normal right = normal_of(scene::pattern::Gradient{{1, 0, 0}}, -1);
    scene::Normal avg = normal_of(scene::pattern::Average{});
    avg.normal_map = {{1, shared(left)}, {1, shared(right)}};
    const glm::dvec3 p{0.3, 0.2, 0.37};
    expect_near(perturbed_normal(avg, kFacing, p), kFacing);  // opposite tilts cancel
    avg.normal_map = {{3, shared(left)}, {1, shared(right)}};
    const glm::dvec3 l = perturbed_normal(left, kFacing, p), r = perturbed_normal(right, kFacing, p);
    expect_near(perturbed_normal(avg, kFacing, p), glm::normalize(0.75 * l + 0.25 * r));
}

// bumps adds the amount times POV's vector noise (at the pattern-space point); wrinkles adds
// ten octaves of its absolute value, so it leans towards +x+y+z.
TEST(Normal, NoiseForms) {
    const glm::dvec3 p{1.3, -2.7, 0.37};
    glm::dvec3 n(0, 0, -1);
    apply_form(scene::pattern::Bumps{}, normal_of(scene::pattern::Bumps{}, 2), p, n);
    expect_near(n, glm::dvec3(0, 0, -1) + 2.0 * noise::dnoise(p));
    // POV's DNoise at this point (the noise module's reference value).
    expect_near(noise::dnoise(p), {0.462106769680104, -0.073638712776967, -0.210533608108356}, 1e-12);

    glm::dvec3 w(0);
    apply_form(scene::pattern::Wrinkles{}, normal_of(scene::pattern::Wrinkles{}, 1), p, w);
    EXPECT_GT(w.x, 0);
    EXPECT_GT(w.y, 0);
    EXPECT_GT(w.z, 0);
    EXPECT_GE(w.x, std::fabs(noise::dnoise(p).x));  // the first octave, and more

    scene::Normal on_the_move = normal_of(scene::pattern::Bumps{}, 1);
    on_the_move.pattern.steps.add_transform(scaled(glm::dvec3(0.1)));
    const glm::dvec3 q{0.13, -0.27, 0.037};  // pattern point p
    expect_near(perturbed_normal(on_the_move, {0, 0, -1}, q),
                glm::normalize(glm::dvec3(0, 0, -1) + noise::dnoise(p)), 1e-12);
}

// facets replace the normal (the amount does not count). Without coords the result depends on
// the normal alone and is the same across a facet; with coords it depends on the point's cell.
TEST(Normal, Facets) {
    scene::pattern::Facets by_normal;
    by_normal.size = 0.3;
    scene::Normal n = normal_of(by_normal, 0.5);
    const glm::dvec3 raw = glm::normalize(glm::dvec3(0.3, 0.2, -1));
    const glm::dvec3 a = perturbed_normal(n, raw, {0, 0, 0});
    EXPECT_NEAR(glm::length(a), 1.0, 1e-15);
    EXPECT_EQ(perturbed_normal(n, raw, {5, -3, 2}), a);  // anywhere
    n.amount = 7;
    EXPECT_EQ(perturbed_normal(n, raw, {0, 0, 0}), a);
    const glm::dvec3 near_raw = glm::normalize(raw + glm::dvec3(1e-6, 0, 0));
    EXPECT_EQ(perturbed_normal(n, near_raw, {0, 0, 0}), a);  // the same facet

    scene::pattern::Facets by_point;
    by_point.coords = 0.5;
    const scene::Normal c = normal_of(by_point);
    const glm::dvec3 here = perturbed_normal(c, raw, {0.31, 0.22, 0.05});
    EXPECT_NEAR(glm::length(here), 1.0, 1e-15);
    EXPECT_NE(here, raw);
    // A tilt tangent to the normal: never turned past the surface.
    for (double x = -2; x < 2; x += 0.37)
        EXPECT_GT(glm::dot(perturbed_normal(c, raw, {x, 0.3 * x, 0.1}), raw), 0) << x;
}

TEST(Normal, QuiltLeansAwayFromTheCubeCentre) {
    const scene::Normal quilt = normal_of(scene::pattern::Quilted{}, 1);
    expect_near(perturbed_normal(quilt, kFacing, {0.5, 0.5, 0.5}), kFacing);  // the centre
    const glm::dvec3 off = perturbed_normal(quilt, kFacing, {0.8, 0.5, 0.3});
    EXPECT_GT(off.x, 0);  // towards +x, where the point lies from the centre
    EXPECT_NEAR(off.y, 0, 1e-15);
}

}  // namespace
}  // namespace lumen::render
