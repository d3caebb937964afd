// Warped points against values read back from povray 3.7 renders (a plane whose pigment
// encodes the pattern point as its colour, 16-bit output).
#include <gtest/gtest.h>

#include "render/patterns/warps.hpp"

namespace lumen::render::test {
namespace {

namespace warp = scene::warp;

void expect_near(const glm::dvec3& got, const glm::dvec3& want, double tol = 2e-4) {
    EXPECT_NEAR(got.x, want.x, tol);
    EXPECT_NEAR(got.y, want.y, tol);
    EXPECT_NEAR(got.z, want.z, tol);
}

// Each block shows the first one moved by the offset once per block; odd blocks mirror the
// flipped axes, and flipping the repeat axis itself keeps the block in place.
TEST(Warps, RepeatOffsetAndFlip) {
    warp::Repeat r;
    r.direction = {1, 0, 0};
    r.offset = {0, 1, 0};
    r.flip = {1, 0, 0};
    expect_near(warp_point(r, {-1.125, 0.625, 0}), {0.875, -1.375, 0});  // block -2: even
    expect_near(warp_point(r, {1.25, 0.5, 0.3}), {0.75, 1.5, 0.3});       // block 1: flipped
    r.flip = {0, 1, 1};
    expect_near(warp_point(r, {1.25, 0.5, 0.3}), {0.25, 0.5, -0.3});
}

TEST(Warps, BlackHole) {
    warp::BlackHole b;
    b.radius = 1.5;
    expect_near(warp_point(b, {-0.375, 0.625, 0}), {-0.4741, 0.7902, 0});
    b.inverse = true;
    expect_near(warp_point(b, {0.375, 0.625, 0}), {0.2759, 0.4598, 0});
    b.inverse = false;
    b.falloff = 0.5;
    b.strength = 3;  // capped: the point moves by its whole distance
    expect_near(warp_point(b, {0.375, 0.625, 0}), {0.75, 1.25, 0});
    expect_near(warp_point(b, {2, 0, 0}), {2, 0, 0});  // outside the radius
    b.type = 1;
    expect_near(warp_point(b, {0.375, 0.625, 0}), {0.375, 0.625, 0});
}

TEST(Warps, RepeatedBlackHoleUsesTheNearestCellsCentre) {
    warp::BlackHole b;
    b.centre = {1, 1, 0};
    b.repeat = {2, 2, 0};
    expect_near(warp_point(b, {-0.375, 0.625, 0}), {-0.3290, 0.5975, 0});
    expect_near(warp_point(b, {1.125, 0.625, 0}), {1.1707, 0.4879, 0});
}

TEST(Warps, MappingWarps) {
    warp::Mapping m;
    m.shape = warp::Mapping::Shape::Cylindrical;
    // The angle from +x towards +z, the height, the distance from the axis.
    expect_near(warp_point(m, {0.375, 0, 0.125}), {0.0512, 0, 0.3953});
    expect_near(warp_point(m, {0.375, 0, -0.625}), {0.8360, 0, 0.7289});
    m.dist_exp = 1;  // scales the angle only
    expect_near(warp_point(m, {-1.125, 0.625, 0}), {0.5625, 0.625, 1.125});
    m.dist_exp = 0;
    m.orientation = {0, 1, 0};
    expect_near(warp_point(m, {-1.125, 1.375, 0}), {0.5, -1.125, 1.375});
    m.shape = warp::Mapping::Shape::Planar;
    m.offset = 0.3;
    expect_near(warp_point(m, {-1.875, 1.1908, 7}), {-1.875, -0.3, 1.1908});
    m.shape = warp::Mapping::Shape::Cubic;
    expect_near(warp_point(m, {2, 1, -1}), {0.75 - 0.5 / 8, 1.0 / 3 + 1.5 / 6, 2});
    expect_near(warp_point(m, {0, 0, 0}), {0, 0, 0});
}

}  // namespace
}  // namespace lumen::render::test
