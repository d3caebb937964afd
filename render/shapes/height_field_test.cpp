// height_field: depths and normals of the two triangles per cell, the water level's box,
// smooth normals and their short quantisation, inside against the hits a CSG parent sees.
#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "render/shapes/height_field.hpp"

namespace lumen::render {
namespace {

scene::HeightField field(int columns, int rows, std::vector<uint16_t> heights, double water = 0,
                         bool smooth = false) {
    scene::HeightField h;
    h.columns = columns;
    h.rows = rows;
    h.heights = std::make_shared<const std::vector<uint16_t>>(std::move(heights));
    h.water_level = water;
    h.smooth = smooth;
    return h;
}

std::optional<ShapeHit> hit(const HeightFieldShape& s, glm::dvec3 o, glm::dvec3 d, double tmin = 1e-6) {
    ShapeHit h;
    if (!intersect(s, {o, glm::normalize(d)}, tmin, 1e30, h)) return std::nullopt;
    return h;
}

TEST(HeightField, FlatFieldAtItsHeight) {
    auto s = make_height_field(field(3, 3, std::vector<uint16_t>(9, 32768)), {});
    ASSERT_TRUE(s->valid);
    auto h = hit(*s, {0.3, 10, 0.6}, {0, -1, 0});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 9.5, 1e-12);  // 32768 / 65536
    EXPECT_NEAR(glm::normalize(h->normal).y, 1, 1e-12);
    EXPECT_FALSE(hit(*s, {1.3, 10, 0.6}, {0, -1, 0}));  // beside the unit square
}

TEST(HeightField, EachCellIsTwoTrianglesSplitFromXPlusOneToZPlusOne) {
    // One cell, only the far corner (x+1, z+1) raised: the triangle (x,z)(x+1,z)(x,z+1) stays
    // flat at 0, the other rises toward the corner.
    auto s = make_height_field(field(2, 2, {0, 0, 0, 65535}, 0), {});
    auto low = hit(*s, {0.2, 5, 0.2}, {0, -1, 0});
    ASSERT_TRUE(low);
    EXPECT_NEAR(5 - low->t, 0, 1e-12);
    auto high = hit(*s, {0.8, 5, 0.8}, {0, -1, 0});
    ASSERT_TRUE(high);
    // The plane through (1,0,0), (0,0,1), (1,h,1): y = h (x + z - 1) at (0.8, 0.8).
    const double top = 65535.0 / 65536.0;
    EXPECT_NEAR(5 - high->t, top * 0.6, 1e-9);
    const glm::dvec3 n = glm::normalize(high->normal);
    const glm::dvec3 expect = glm::normalize(glm::dvec3(-top, 1, -top));
    EXPECT_NEAR(glm::dot(n, expect), 1, 1e-12);
}

TEST(HeightField, NothingBelowTheWaterLevelIsDrawn) {
    // A ramp along x from 0 to full height, water at half height.
    std::vector<uint16_t> ramp;
    for (int z = 0; z < 3; ++z)
        for (int x = 0; x < 5; ++x) ramp.push_back(uint16_t(x * 16383));
    auto dry = make_height_field(field(5, 3, ramp), {});
    auto wet = make_height_field(field(5, 3, ramp, 0.5), {});
    EXPECT_TRUE(hit(*dry, {0.2, 5, 0.5}, {0, -1, 0}));
    EXPECT_FALSE(hit(*wet, {0.2, 5, 0.5}, {0, -1, 0}));
    auto above = hit(*wet, {0.9, 5, 0.5}, {0, -1, 0});
    ASSERT_TRUE(above);
    EXPECT_NEAR(5 - above->t, 0.9 * 4 * 16383 / 65536.0, 1e-9);
    // Below the water is inside, as is all that lies under the surface; above and beside are
    // not.
    EXPECT_TRUE(inside(*wet, {0.2, 0.3, 0.5}));
    EXPECT_FALSE(inside(*dry, {0.2, 0.3, 0.5}));
    EXPECT_TRUE(inside(*dry, {0.9, -5, 0.5}));
    EXPECT_TRUE(inside(*dry, {0.9, 0.5, 0.5}));
    EXPECT_FALSE(inside(*dry, {0.9, 0.95, 0.5}));
    EXPECT_FALSE(inside(*dry, {1.1, 0.1, 0.5}));
    EXPECT_FALSE(inside(*dry, {0.5, 2, 0.5}));  // above the box
}

TEST(HeightField, HitsAlongARayAlternateInsideAndOutside) {
    // A ridge across z: a horizontal ray along x enters and leaves it.
    std::vector<uint16_t> ridge;
    for (int z = 0; z < 4; ++z)
        for (int x : {0, 20000, 60000, 50000, 10000, 0, 0}) ridge.push_back(uint16_t(x)), (void)z;
    auto s = make_height_field(field(7, 4, ridge), {});
    const glm::dvec3 o{-1, 0.3, 0.5}, d{1, 0, 0};
    double from = 1e-6;
    std::vector<double> ts;
    for (int k = 0; k < 10; ++k) {
        auto h = hit(*s, o, d, from);
        if (!h) break;
        ts.push_back(h->t);
        from = h->t;
    }
    ASSERT_EQ(ts.size(), 2u);
    const glm::dvec3 mid = o + 0.5 * (ts[0] + ts[1]) * d;
    EXPECT_TRUE(inside(*s, mid));
    EXPECT_FALSE(inside(*s, o + (ts[0] - 1e-3) * d));
    EXPECT_FALSE(inside(*s, o + (ts[1] + 1e-3) * d));
}

TEST(HeightField, TransformedFieldKeepsWorldDepths) {
    scene::Transform xf;
    xf.m = glm::dmat4(glm::dvec4(4, 0, 0, 0), glm::dvec4(0, 2, 0, 0), glm::dvec4(0, 0, 3, 0),
                      glm::dvec4(-2, 1, 0, 1));
    xf.inv = glm::inverse(xf.m);
    auto s = make_height_field(field(3, 3, std::vector<uint16_t>(9, 16384)), xf);
    auto h = hit(*s, {0, 10, 1}, {0, -1, 0});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 10 - (1 + 2 * 0.25), 1e-9);
    const Aabb b = bounds(*s);
    EXPECT_NEAR(b.lo.x, -2, 1e-12);
    EXPECT_NEAR(b.hi.x, 2, 1e-12);
    EXPECT_NEAR(b.hi.z, 3, 1e-12);
}

// A bowl: smooth normals tilt toward the centre, vary continuously across cell edges, and
// are stored as int(32767 n).
TEST(HeightField, SmoothNormalsBlendTheQuantisedVertexNormals) {
    std::vector<uint16_t> bowl;
    for (int z = 0; z < 5; ++z)
        for (int x = 0; x < 5; ++x) bowl.push_back(uint16_t(3000 * ((x - 2) * (x - 2) + (z - 2) * (z - 2))));
    auto flat = make_height_field(field(5, 5, bowl), {});
    auto smooth = make_height_field(field(5, 5, bowl, 0, true), {});
    ASSERT_EQ(smooth->normals.size(), 25u);
    for (const auto& n : smooth->normals) {
        const double len = std::sqrt(double(n[0]) * n[0] + double(n[1]) * n[1] + double(n[2]) * n[2]);
        EXPECT_LE(len, 32767.0 * (1 + 1e-9));
        EXPECT_GT(len, 32767.0 - 2);  // truncation loses less than one unit per component
        EXPECT_GT(n[1], 0);
    }
    // The centre vertex's normal is straight up.
    EXPECT_EQ(smooth->normals[12][0], 0);
    EXPECT_EQ(smooth->normals[12][2], 0);
    // Across the edge x = 0.5 (grid 2) between two cells the smooth normal is continuous,
    // the flat one jumps.
    auto n_at = [&](const HeightFieldShape& s, double x) {
        auto h = hit(s, {x, 5, 0.3}, {0, -1, 0});
        EXPECT_TRUE(h);
        return h ? glm::normalize(h->normal) : glm::dvec3(0);
    };
    const double e = 1e-7;
    EXPECT_NEAR(glm::dot(n_at(*smooth, 0.25 - e), n_at(*smooth, 0.25 + e)), 1, 1e-9);
    EXPECT_LT(glm::dot(n_at(*flat, 0.25 - e), n_at(*flat, 0.25 + e)), 0.9999);
    // Left of the centre the surface rises toward -x: the normal leans toward +x.
    EXPECT_GT(n_at(*smooth, 0.3).x, 0);
}

TEST(HeightField, BadGridsAreNeverHit) {
    auto small = make_height_field(field(1, 3, {1, 2, 3}), {});
    EXPECT_FALSE(small->valid);
    EXPECT_FALSE(hit(*small, {0.5, 5, 0.5}, {0, -1, 0}));
    EXPECT_TRUE(bounds(*small).empty());
    scene::HeightField wrong = field(3, 3, {1, 2});
    EXPECT_FALSE(make_height_field(wrong, {})->valid);
}

}  // namespace
}  // namespace lumen::render
