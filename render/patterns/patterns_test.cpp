// Raw values of the non-noise patterns of render/patterns/ at single points, worked out from
// POV-Ray's definitions (and, for slope, read back from povray 3.7 renders).
#include <gtest/gtest.h>

#include <cmath>

#include "render/patterns/fractals.hpp"
#include "render/patterns/pattern_sources.hpp"
#include "render/patterns/periodic.hpp"
#include "render/patterns/surface_patterns.hpp"
#include "render/patterns/tilings.hpp"

namespace lumen::render::test {
namespace {

namespace pattern = scene::pattern;

TEST(Patterns, MandelEscapeCountAndInterior) {
    pattern::Mandel m;
    m.iterations = 10;
    m.exterior = {1, 1};  // the 0-based step it escaped at, over the iterations
    EXPECT_DOUBLE_EQ(evaluate(m, {1, 1, 0}), 0.0);   // (1+1i)² + c = 1+3i: out at once
    EXPECT_DOUBLE_EQ(evaluate(m, {0.5, 0, 0}), 0.3);  // 0.75, 1.0625, 1.6289, 3.15: step 3
    EXPECT_DOUBLE_EQ(evaluate(m, {0, 0, 0}), 1.0);    // interior 0, factor 1
    m.interior = {1, 2};  // the orbit's least distance from 0, times the factor
    EXPECT_NEAR(evaluate(m, {-0.1, 0, 0}), 2 * 0.09, 1e-12);  // |z1| = 0.09 is the least
    m.interior = {6, 0.5};  // POV-Ray's a² + b²·f
    pattern::Mandel n = m;
    n.iterations = 1;
    // One step from c = (0.1, 0.2): z = (0.1² − 0.2² + 0.1, 2·0.1·0.2 + 0.2) = (0.07, 0.24).
    EXPECT_NEAR(evaluate(n, {0.1, 0.2, 0}), 0.07 * 0.07 + 0.24 * 0.24 * 0.5, 1e-15);
}

TEST(Patterns, GenericPowerMatchesTheExpandedOnes) {
    pattern::Julia j;
    j.iterations = 1;
    j.exterior = {2, 1};  // the escape point's x
    j.interior = {2, 1};
    j.c = {0.1, -0.2};
    // z = 0.9 + 0.4i: z² = 0.65 + 0.72i, z⁴ = −0.0959 + 0.936i, z⁵ = −0.46071 + 0.80404i.
    j.exponent = 5;
    EXPECT_NEAR(evaluate(j, {0.9, 0.4, 0}), -0.46071 + 0.1, 1e-12);
    j.exponent = 4;
    EXPECT_NEAR(evaluate(j, {0.9, 0.4, 0}), -0.0959 + 0.1, 1e-12);
}

TEST(Patterns, MagnetEscapesNearOne) {
    pattern::Magnet m;
    m.iterations = 5;
    m.exterior = {1, 1};
    // magnet 1 mandel at c = 1: z1 = ((0 + c − 1) / (0 + c − 2))² = 0, a fixed point that
    // never escapes (interior 0, factor 1).
    EXPECT_DOUBLE_EQ(evaluate(m, {1, 0, 0}), 1.0);
    m.julia = true;
    m.c = {0, 0};
    // From z = 1.001: w = (z² − 1)/(2z − 2) = (z + 1)/2, z1 = w² = 1.001 within 0.01 of 1.
    EXPECT_DOUBLE_EQ(evaluate(m, {1.001, 0, 0}), 0.0);
}

TEST(Patterns, LeopardAndQuilted) {
    EXPECT_NEAR(evaluate(pattern::Leopard{}, {1, 2, 3}),
                std::pow((std::sin(1.0) + std::sin(2.0) + std::sin(3.0)) / 3, 2), 1e-15);
    const pattern::Quilted q;  // control0 = control1 = 1: the shaping cubic is 1 − (1 − t)³
    EXPECT_NEAR(evaluate(q, {0.5, 0.5, 0.5}), 0, 1e-15);  // the cube's centre
    // v = (0.25, −0.25, 0), t = |v|
    const double t = std::sqrt(0.125), shape = (1 - std::pow(1 - t, 3)) * 1.154700538;
    EXPECT_NEAR(evaluate(q, {2.75, -0.75, 0.5}), 0.5 * shape / 3, 1e-12);
}

TEST(Patterns, CubicFacesAndTiling) {
    EXPECT_EQ(evaluate(pattern::Cubic{}, {2, 1, -1}), 0);
    EXPECT_EQ(evaluate(pattern::Cubic{}, {1, 2, 1}), 1);
    EXPECT_EQ(evaluate(pattern::Cubic{}, {1, 1, 2}), 2);
    EXPECT_EQ(evaluate(pattern::Cubic{}, {-2, 1, 1}), 3);
    EXPECT_EQ(evaluate(pattern::Cubic{}, {1, -2, 1}), 4);
    EXPECT_EQ(evaluate(pattern::Cubic{}, {1, 1, -2}), 5);
    EXPECT_EQ(evaluate(pattern::Cubic{}, {1, 1, 1}), 0);  // ties go to +x
    pattern::Tiling t;  // 1: square tiles, 0 at the centre, 1 on the edge
    EXPECT_NEAR(evaluate(t, {0.5, 7, 1.5}), 0, 1e-15);
    EXPECT_NEAR(evaluate(t, {0.25, 0, 0.5}), 0.5, 1e-15);
    t.type = 10;  // odd rows shifted by half a tile
    EXPECT_NEAR(evaluate(t, {0.5, 0, 0.5}), 0, 1e-15);
    EXPECT_NEAR(evaluate(t, {0.5, 0, 1.5}), 1, 1e-15);
    t.type = 3;  // up-pointing triangles in [0, 0.5], down-pointing ones in [0.5, 1]
    EXPECT_LE(evaluate(t, {0.5, 0, 0.2}), 0.5);
    EXPECT_GE(evaluate(t, {0.0, 0, 0.6}), 0.5);
}

// Read back from povray renders of a plane y = 0 seen from above.
TEST(Patterns, SlopeAndAoi) {
    const SurfacePoint up{{0, 0, 0}, {0, 1, 0}, {0, -1, 0}};
    pattern::Slope s;
    EXPECT_DOUBLE_EQ(evaluate(s, {0, 0, 0}, &up), 1 - 1e-10);  // facing v: just below 1
    EXPECT_DOUBLE_EQ(evaluate(s, {0, 0, 0}, nullptr), 0);    // no surface
    s.direction = glm::normalize(glm::dvec3(1, 1, 0));
    EXPECT_NEAR(evaluate(s, {0, 0, 0}, &up), 0.75, 1e-12);
    s.direction = {5, 10, 0};
    s.point_at = true;
    EXPECT_NEAR(evaluate(s, {0, 0, 0}, &up), 55863 / 65535.0, 2e-5);
    s = {};
    s.length = 2;
    s.altitude = {0, 1, 0};
    s.altitude_length = 1;
    s.altitude_range = {-0.5, 0.5};
    EXPECT_NEAR(evaluate(s, {0, -0.2, 0}, &up), 50244 / 65535.0, 2e-5);
    EXPECT_DOUBLE_EQ(evaluate(pattern::Aoi{}, {0, 0, 0}, &up), 1);
    const SurfacePoint grazing{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}};
    EXPECT_DOUBLE_EQ(evaluate(pattern::Aoi{}, {0, 0, 0}, &grazing), 0.5);
}

TEST(Patterns, DensityFileNearestAndTrilinear) {
    auto grid = std::make_shared<pattern::DensityGrid>();
    grid->nx = 2, grid->ny = 1, grid->nz = 1;
    grid->values = {0.2, 0.6};
    pattern::DensityFile d;
    d.grid = grid;
    EXPECT_DOUBLE_EQ(evaluate(d, {0.3, 0.5, 0.5}), 0.2);
    EXPECT_DOUBLE_EQ(evaluate(d, {0.7, 0.5, 0.5}), 0.6);
    EXPECT_DOUBLE_EQ(evaluate(d, {1.0, 0.5, 0.5}), 0.0);  // outside the unit cube
    d.interpolate = 1;  // voxel i sits at i/n; the last one blends with the first
    EXPECT_DOUBLE_EQ(evaluate(d, {0.25, 0.5, 0.5}), 0.4);
    EXPECT_DOUBLE_EQ(evaluate(d, {0.75, 0.5, 0.5}), 0.4);
    d.interpolate = 11;  // used modulo 10
    EXPECT_DOUBLE_EQ(evaluate(d, {0.25, 0.5, 0.5}), 0.4);
}

// Catmull-Rom halfway between voxels 0 and 1 weighs voxels −1, 0, 1, 2 by −1/16, 9/16, 9/16,
// −1/16; voxel −1 is (2⁶⁴ − 1) mod n: voxel 0 for n = 5, voxel 3 for n = 4.
TEST(Patterns, DensityFileTricubic) {
    auto grid = std::make_shared<pattern::DensityGrid>();
    grid->nx = 5, grid->ny = 1, grid->nz = 1;
    grid->values = {0.1, 0.5, 0.9, 0.3, 0.7};
    pattern::DensityFile d;
    d.grid = grid;
    d.interpolate = 2;
    const double w = 1 / 16.0, c = 9 / 16.0;
    EXPECT_NEAR(evaluate(d, {0.1, 0.5, 0.5}), -w * 0.1 + c * 0.1 + c * 0.5 - w * 0.9, 1e-12);
    grid->nx = 4;
    grid->values = {0.1, 0.5, 0.9, 0.3};
    EXPECT_NEAR(evaluate(d, {0.125, 0.5, 0.5}), -w * 0.3 + c * 0.1 + c * 0.5 - w * 0.9, 1e-12);
    grid->values = {0, 0, 1, 0};  // beside a sharp edge the cubic dips below 0: held at 0
    EXPECT_DOUBLE_EQ(evaluate(d, {0.125, 0.5, 0.5}), 0);
}

}  // namespace
}  // namespace lumen::render::test
