// Each shape's uv under uv_mapping at known points (render/surface_uv.cpp), and the swept
// shapes' and meshes' parametric v as their intersections report it.
#include <gtest/gtest.h>

#include "render/shapes.hpp"
#include "render/surface_uv.hpp"

namespace lumen::render {
namespace {

glm::dvec2 uv_at(const ShapeData& shape, const glm::dvec3& p, const glm::dvec3& normal = {0, 1, 0}) {
    ShapeHit hit;
    hit.normal = normal;
    return surface_uv(shape, p, p + glm::dvec3(10, 20, 30), hit);
}

// The uv where the ray from `o` along `d` first meets the shape.
glm::dvec2 uv_of_ray(const ShapeData& shape, const glm::dvec3& o, const glm::dvec3& d,
                     glm::dvec3* point = nullptr) {
    ShapeHit hit;
    const LocalRay r{o, d};
    EXPECT_TRUE(shape_intersect(shape, r, 1e-6, 1e9, hit));
    if (point) *point = r.at(hit.t);
    return surface_uv(shape, r.at(hit.t), r.at(hit.t), hit);
}

void expect_uv(const glm::dvec2& got, double u, double v) {
    EXPECT_NEAR(got.x, u, 1e-12);
    EXPECT_NEAR(got.y, v, 1e-12);
}

TEST(SurfaceUv, TurnFractionStartsAlongXAndTurnsTowardZ) {
    EXPECT_DOUBLE_EQ(turn_fraction(1, 0), 0);
    EXPECT_DOUBLE_EQ(turn_fraction(0, 1), 0.25);
    EXPECT_DOUBLE_EQ(turn_fraction(-1, 0), 0.5);
    EXPECT_DOUBLE_EQ(turn_fraction(0, -1), 0.75);
    EXPECT_DOUBLE_EQ(turn_fraction(1e-6, -1e-6), 0);  // on the axis
}

TEST(SurfaceUv, SphereLongitudeAndLatitude) {
    const ShapeData s = make_sphere({{1, 2, 3}, 2});
    expect_uv(uv_at(s, {1, 2, 1}), 0.75, 0.5);  // facing -z
    expect_uv(uv_at(s, {3, 2, 3}), 0, 0.5);
    expect_uv(uv_at(s, {1, 2, 5}), 0.25, 0.5);
    expect_uv(uv_at(s, {1, 4, 3}), 0, 1);       // north pole
    expect_uv(uv_at(s, {1, 0, 3}), 0, 0);
    const double h = std::sqrt(2.0);
    expect_uv(uv_at(s, {1 - h, 2 + h, 3}), 0.5, 0.75);
}

TEST(SurfaceUv, BoxFacesUnfoldIntoACross) {
    const ShapeData b = make_box({{0, 0, 0}, {2, 4, 8}});
    const glm::dvec3 q{0.5, 1, 6};  // (0.25, 0.25, 0.75) across the box
    expect_uv(uv_at(b, {0, q.y, q.z}, {-1, 0, 0}), 0.75 / 4, 1.0 / 3 + 0.25 / 3);
    expect_uv(uv_at(b, {2, q.y, q.z}, {1, 0, 0}), 0.75 - 0.75 / 4, 1.0 / 3 + 0.25 / 3);
    expect_uv(uv_at(b, {q.x, 0, q.z}, {0, -1, 0}), 0.25 + 0.25 / 4, 0.75 / 3);
    expect_uv(uv_at(b, {q.x, 4, q.z}, {0, 1, 0}), 0.25 + 0.25 / 4, 1 - 0.75 / 3);
    expect_uv(uv_at(b, {q.x, q.y, 0}, {0, 0, -1}), 1 - 0.25 / 4, 1.0 / 3 + 0.25 / 3);
    expect_uv(uv_at(b, {q.x, q.y, 8}, {0, 0, 1}), 0.25 + 0.25 / 4, 1.0 / 3 + 0.25 / 3);
}

TEST(SurfaceUv, TorusAroundTheRingAndTheTube) {
    const ShapeData t = make_torus({2, 0.5});
    expect_uv(uv_at(t, {2.5, 0, 0}), 0.5, 0.5);
    expect_uv(uv_at(t, {0, 0, -2.5}), 0.75, 0.5);
    expect_uv(uv_at(t, {0, 0, 2.5}), 0.25, 0.5);
    expect_uv(uv_at(t, {2, 0.5, 0}), 0.5, 0.75);
    expect_uv(uv_at(t, {2, -0.5, 0}), 0.5, 0.25);
}

TEST(SurfaceUv, ShapesWithoutUvGiveWorldXAndY) {
    const ShapeData p = make_plane({{0, 1, 0}, 0});
    expect_uv(uv_at(p, {0.5, 0, -2}), 10.5, 20);
}

TEST(SurfaceUv, LatheVIsSegmentPlusSplineParameter) {
    scene::Lathe l;
    l.points = {{1, 0}, {1, 1}, {1, 3}};  // two straight segments up a cylinder of radius 1
    const ShapeData s = make_lathe(l);
    expect_uv(uv_of_ray(s, {0, 0.5, -5}, {0, 0, 1}), 0.75, 0.25);
    expect_uv(uv_of_ray(s, {5, 2.5, 0}, {-1, 0, 0}), 0, 0.5 + 0.75 / 2);
}

TEST(SurfaceUv, SorSidesBaseAndCap) {
    scene::Sor so;
    so.points = {{1, -1}, {1, 0}, {1, 1}, {1, 2}, {1, 3}};  // a cylinder: two segments, y 0..2
    const ShapeData s = make_sor(so);
    expect_uv(uv_of_ray(s, {-5, 0.5, 0}, {1, 0, 0}), 0.5, 0.25);
    expect_uv(uv_of_ray(s, {0, 1.5, 5}, {0, 0, -1}), 0.25, 0.75);
    expect_uv(uv_of_ray(s, {0.5, -5, 0}, {0, 1, 0}), 0, 0.5 - 1);  // base: r/r_base - 1
    expect_uv(uv_of_ray(s, {0, 5, -0.25}, {0, -1, 0}), 0.75, 2 - 0.25);  // cap: 2 - r/r_cap
}

TEST(SurfaceUv, MeshBlendsItsCornerUvsAndPatchesMapOntoTheirCorners) {
    scene::Mesh m;
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.uvs = {{0.2, 0.4}, {1, 0}, {0, 1}};
    scene::Mesh::Face f;
    f.v = {0, 1, 2};
    f.uv = {0, 1, 2};
    m.faces = {f};
    const ShapeData mesh = make_mesh(m);
    // Barycentric (0.5, 0.25, 0.25) at (0.25, 0.25).
    expect_uv(uv_of_ray(mesh, {0.25, 0.25, -1}, {0, 0, 1}), 0.5 * 0.2 + 0.25, 0.5 * 0.4 + 0.25);
    scene::Mesh patch = m;
    patch.uvs = {{0, 0}, {1, 0}, {0, 1}};  // patch (u, v) per corner
    patch.patch_corners = {{0, 0}, {2, 0}, {2, 4}, {0, 4}};
    const ShapeData p = make_mesh(patch);
    // (u, v) = (0.25, 0.25): lerp(lerp(s0, s1, v), lerp(s3, s2, v), u).
    expect_uv(uv_of_ray(p, {0.25, 0.25, -1}, {0, 0, 1}), 0.5, 1);
    scene::Mesh bare = m;
    bare.faces.edit()[0].uv = {-1, -1, -1};
    expect_uv(uv_of_ray(make_mesh(bare), {0.25, 0.25, -1}, {0, 0, 1}), 0, 0);
}

}  // namespace
}  // namespace lumen::render
