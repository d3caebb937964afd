#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "render/camera.hpp"
#include "scene/object.hpp"

namespace lumen::render {
namespace {

TEST(Camera, DefaultPerspectiveUsesHalfPixelOffsetAndFlipsY) {
    scene::Camera c;  // right 1.33, up 1, direction 1
    const CameraModel cam(c, 64, 48);
    const Ray top_left = *cam.ray(0, 0);
    const glm::dvec3 expected =
        glm::normalize(glm::dvec3((0.5 / 64 - 0.5) * 1.33, 0.5 - 0.5 / 48, 1.0));
    EXPECT_NEAR(top_left.dir.x, expected.x, 1e-12);
    EXPECT_NEAR(top_left.dir.y, expected.y, 1e-12);
    EXPECT_GT(top_left.dir.y, 0);  // the top row looks up
    EXPECT_NEAR(glm::length(cam.ray(17.3, 5.2)->dir), 1.0, 1e-12);
    // The centre of the image lies between pixels 31 and 32.
    const Ray centre = *cam.ray(31.5, 23.5);
    EXPECT_NEAR(centre.dir.x, 0, 1e-12);
    EXPECT_NEAR(centre.dir.y, 0, 1e-12);
}

TEST(Camera, OrthographicMovesTheOriginNotTheDirection) {
    scene::Camera c;
    c.type = scene::CameraType::Orthographic;
    c.location = {0, 0, -10};
    c.right = {4, 0, 0};
    c.up = {0, 3, 0};
    const CameraModel cam(c, 40, 30);
    const Ray r = *cam.ray(0, 0);
    EXPECT_NEAR(r.origin.x, (0.5 / 40 - 0.5) * 4, 1e-12);
    EXPECT_NEAR(r.origin.y, (0.5 - 0.5 / 30) * 3, 1e-12);
    EXPECT_NEAR(r.dir.z, 1, 1e-12);
    EXPECT_NEAR(r.dir.x, 0, 1e-12);
}

TEST(Camera, NegativeRightMirrorsTheImage) {
    scene::Camera c;
    c.right = {-1.33, 0, 0};
    const CameraModel cam(c, 10, 10);
    EXPECT_GT(cam.ray(0, 5)->dir.x, 0);
}


scene::Camera typed(scene::CameraType type) {
    scene::Camera c;
    c.type = type;
    return c;
}

TEST(Camera, FisheyeHasNoRayOutsideItsCircle) {
    scene::Camera c = typed(scene::CameraType::Fisheye);
    c.right = {1.33, 0, 0};
    const CameraModel cam(c, 64, 48);
    EXPECT_FALSE(cam.ray(0, 0).has_value());  // the corner lies outside the circle
    const Ray centre = *cam.ray(31.5, 23.5);
    EXPECT_NEAR(centre.dir.z, 1, 1e-12);
    // On the circle's rim the ray is angle/2 = 45 degrees off the axis.
    const Ray top = *cam.ray(31.5, -0.5);
    EXPECT_NEAR(std::acos(top.dir.z), M_PI / 4, 1e-9);
}

TEST(Camera, OmnimaxShowsNothingFarBelowTheHorizon) {
    scene::Camera c = typed(scene::CameraType::Omnimax);
    c.right = {1, 0, 0};  // square: the dome's y is not stretched
    const CameraModel cam(c, 64, 64);
    EXPECT_FALSE(cam.ray(31.5, 62).has_value());  // near the bottom of the dome
    EXPECT_TRUE(cam.ray(31.5, 1).has_value());    // the top is seen
}

TEST(Camera, PanoramicPolesStayFinite) {
    const CameraModel cam(typed(scene::CameraType::Panoramic), 40, 30);
    const Ray pole = *cam.ray(10, -0.5);  // b = pi/2 exactly: tan clamped to 1e10
    EXPECT_TRUE(std::isfinite(pole.dir.y));
    EXPECT_NEAR(pole.dir.y, 1, 1e-9);
}

TEST(Camera, SphericalSpansItsAngles) {
    scene::Camera c = typed(scene::CameraType::Spherical);
    c.angle = 200;
    c.vertical_angle = 60;
    const CameraModel cam(c, 100, 50);
    const Ray left = *cam.ray(-0.5, 24.5);  // the left edge: -100 degrees about up
    EXPECT_NEAR(std::atan2(left.dir.x, left.dir.z), -100 * M_PI / 180, 1e-9);
    const Ray top = *cam.ray(49.5, -0.5);  // the top edge: 30 degrees up
    EXPECT_NEAR(std::asin(top.dir.y), 30 * M_PI / 180, 1e-9);
}

TEST(Camera, CylinderTypesThreeAndFourMoveTheOrigin) {
    for (int type = 1; type <= 4; ++type) {
        scene::Camera c = typed(scene::CameraType::Cylinder);
        c.cylinder_type = type;
        c.up = {0, 2, 0};
        const CameraModel cam(c, 40, 30);
        const Ray corner = *cam.ray(0, 0);
        const bool moves = type >= 3;
        EXPECT_EQ(glm::length(corner.origin) > 0, moves) << type;
        if (type == 3) {
            EXPECT_NEAR(corner.origin.y, (0.5 - 0.5 / 30) * 2, 1e-12);
        }
    }
}

// No projection hands out a NaN direction, even for positions off the image.
TEST(Camera, EveryProjectionGivesUnitFiniteRays) {
    for (int t = 0; t <= int(scene::CameraType::Cylinder); ++t) {
        const CameraModel cam(typed(scene::CameraType(t)), 16, 12);
        for (double y = -3; y <= 15; y += 0.75)
            for (double x = -3; x <= 19; x += 0.75)
                if (const auto r = cam.ray(x, y)) {
                    ASSERT_TRUE(std::isfinite(r->dir.x + r->dir.y + r->dir.z)) << t;
                    EXPECT_NEAR(glm::length(r->dir), 1, 1e-9) << t;
                }
    }
}

}  // namespace
}  // namespace lumen::render

namespace lumen::render {
namespace {

// A mesh of w x h unit triangles, one per pixel in row-major order, each facing +z (POV's
// winding: (P3 - P1) x (P2 - P1)), centred at (column, -row).
std::shared_ptr<scene::Object> pixel_grid(int w, int h) {
    auto obj = std::make_shared<scene::Object>();
    scene::Mesh m;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const glm::dvec3 c(i, -j, 0);
            const int base = int(m.vertices.size());
            for (const glm::dvec3& d : {glm::dvec3(-0.1, -0.1, 0), glm::dvec3(-0.1, 0.2, 0),
                                        glm::dvec3(0.2, -0.1, 0)})
                m.vertices.push_back(c + d);
            scene::Mesh::Face f;
            f.v = {base, base + 1, base + 2};
            m.faces.push_back(f);
        }
    obj->shape = std::move(m);
    return obj;
}

TEST(Camera, MeshCameraRaysLeaveTheFacesInPovRaysOrder) {
    scene::Camera c;
    c.type = scene::CameraType::MeshCamera;
    c.mesh = scene::Camera::MeshRays{};
    c.mesh->meshes = {pixel_grid(4, 3)};
    c.mesh->offset = -0.5;
    const CameraModel cam(c, 4, 3);
    ASSERT_EQ(cam.rays_per_sample(), 1);
    auto r = cam.ray(2, 2);  // row 2 uses face row 1; rows 0 and 1 share face row 0
    ASSERT_TRUE(r);
    EXPECT_NEAR(r->origin.x, 2, 1e-12);  // the centroid
    EXPECT_NEAR(r->origin.y, -1, 1e-12);
    EXPECT_NEAR(r->origin.z, -0.5, 1e-12);  // location.z along the normal
    EXPECT_NEAR(r->dir.z, 1, 1e-12);
    EXPECT_NEAR(cam.ray(1, 0)->origin.y, cam.ray(1, 1)->origin.y, 1e-12);
    // Distribution 1 with two rays: the second falls past the faces and is not shot.
    c.mesh->distribution = 1;
    c.mesh->rays = 2;
    const CameraModel joined(c, 4, 3);
    EXPECT_TRUE(joined.ray(0, 0, 0));
    EXPECT_FALSE(joined.ray(0, 0, 1));
    // Reversed and transformed: the direction turns with the mesh.
    c.mesh->distribution = 0;
    c.mesh->rays = 1;
    c.mesh->reverse = true;
    auto moved = std::make_shared<scene::Object>(*pixel_grid(4, 3));
    moved->transform = {glm::dmat4(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 0, 0, 1), glm::dmat4(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -5, 0, 0, 1)};
    c.mesh->meshes = {moved};
    const CameraModel back(c, 4, 3);
    EXPECT_NEAR(back.ray(0, 0)->dir.z, -1, 1e-12);
    EXPECT_NEAR(back.ray(0, 0)->origin.x, 5, 1e-12);
    // A copy shares its mesh's face table, in its own place; another mesh has its own table.
    c.mesh->reverse = false;
    c.mesh->rays = 3;
    c.mesh->meshes = {pixel_grid(4, 3), nullptr, moved};
    c.mesh->meshes[1] = std::make_shared<scene::Object>(*c.mesh->meshes[0]);
    const CameraModel copies(c, 4, 3);
    EXPECT_EQ(copies.face_tables(), 2u);
    EXPECT_NEAR(copies.ray(0, 0, 2)->origin.x, copies.ray(0, 0, 0)->origin.x + 5, 1e-12);
    EXPECT_NEAR(copies.ray(0, 0, 1)->origin.x, copies.ray(0, 0, 0)->origin.x, 1e-12);
}

// Distribution 3 (uv baking): a mesh whose faces are given with their 3D corners and uvs.
struct UvFace {
    std::array<glm::dvec3, 3> p;
    std::array<glm::dvec2, 3> uv;
};
std::shared_ptr<scene::Object> uv_mesh(const std::vector<UvFace>& faces,
                                       const std::vector<std::array<glm::dvec3, 3>>& normals = {}) {
    auto obj = std::make_shared<scene::Object>();
    scene::Mesh m;
    for (size_t i = 0; i < faces.size(); ++i) {
        scene::Mesh::Face f;
        for (int c = 0; c < 3; ++c) {
            f.v[c] = f.uv[c] = int(m.vertices.size());
            m.vertices.push_back(faces[i].p[c]);
            m.uvs.push_back(faces[i].uv[c]);
            if (i < normals.size()) {
                f.n[c] = int(m.normals.size());
                m.normals.push_back(normals[i][c]);
            }
        }
        m.faces.push_back(f);
    }
    obj->shape = std::move(m);
    return obj;
}

scene::Camera uv_camera(std::shared_ptr<scene::Object> mesh, double offset, bool smooth) {
    scene::Camera c;
    c.type = scene::CameraType::MeshCamera;
    c.mesh = scene::Camera::MeshRays{};
    c.mesh->distribution = 3;
    c.mesh->meshes = {std::move(mesh)};
    c.mesh->offset = offset;
    c.mesh->smooth = smooth;
    return c;
}

// The lower-left half of the uv square on a 2 x 2 square in z = 0 (facing -z by POV's winding).
const UvFace kLowerLeft{{glm::dvec3(0, 0, 0), glm::dvec3(2, 0, 0), glm::dvec3(0, 2, 0)},
                        {glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(0, 1)}};

TEST(Camera, MeshCameraUvRayStartsAtThePixelsPlaceOnTheFirstFaceThere) {
    // A second face with the same uvs further on: the first in mesh order wins.
    UvFace later = kLowerLeft;
    for (glm::dvec3& p : later.p) p.z = 5;
    const CameraModel cam(uv_camera(uv_mesh({kLowerLeft, later}), -0.5, false), 10, 10);
    // Pixel (2, 7): u = 2 / 10, v = 1 - 7 / 10; weights 0.5, 0.2, 0.3.
    const auto r = cam.ray(2, 7);
    ASSERT_TRUE(r);
    EXPECT_NEAR(r->origin.x, 0.4, 1e-12);
    EXPECT_NEAR(r->origin.y, 0.6, 1e-12);
    EXPECT_NEAR(r->origin.z, 0.5, 1e-12);  // location.z along the face normal -z
    EXPECT_NEAR(r->dir.z, -1, 1e-12);
    // POV's row -0.5 is clamped to 0 (v = 1 - 0.5 / 10), its last column 9.5 to 9 (u = 8.5 / 10).
    EXPECT_NEAR(cam.ray(0, 0)->origin.y, 2 * 0.95, 1e-12);
    EXPECT_NEAR(cam.ray(0, 1)->origin.y, 2 * 0.9, 1e-12);
    EXPECT_NEAR(cam.ray(9, 9)->origin.x, 2 * 0.85, 1e-12);
    EXPECT_FALSE(cam.ray(9, 5));  // u 0.85 + v 0.5 lies past the diagonal
}

TEST(Camera, MeshCameraUvSampleOutsideEveryFaceHasNoRay) {
    const CameraModel half(uv_camera(uv_mesh({kLowerLeft}), 0, false), 10, 10);
    EXPECT_FALSE(half.ray(8, 2));  // u 0.8, v 0.8
    // The upper-right half covers it, on the other side of the square.
    const UvFace upper{{glm::dvec3(2, 0, 1), glm::dvec3(2, 2, 1), glm::dvec3(0, 2, 1)},
                       {glm::dvec2(1, 0), glm::dvec2(1, 1), glm::dvec2(0, 1)}};
    const CameraModel full(uv_camera(uv_mesh({kLowerLeft, upper}), 0, false), 10, 10);
    const auto r = full.ray(8, 2);
    ASSERT_TRUE(r);
    EXPECT_NEAR(r->origin.x, 1.6, 1e-12);
    EXPECT_NEAR(r->origin.y, 1.6, 1e-12);
    EXPECT_NEAR(r->origin.z, 1, 1e-12);
}

TEST(Camera, MeshCameraUvSmoothBlendsTheVertexNormals) {
    const std::vector<std::array<glm::dvec3, 3>> normals{
        {glm::dvec3(0, 0, 2), glm::dvec3(1, 0, 0), glm::dvec3(0, 3, 0)}};  // unit once read
    const CameraModel flat(uv_camera(uv_mesh({kLowerLeft}, normals), 0, false), 10, 10);
    EXPECT_NEAR(flat.ray(2, 7)->dir.z, -1, 1e-12);  // no smooth: the face normal
    const CameraModel smooth(uv_camera(uv_mesh({kLowerLeft}, normals), 1, true), 10, 10);
    const auto r = smooth.ray(2, 7);
    ASSERT_TRUE(r);
    // Weights 0.5, 0.2, 0.3: the blend (0.2, 0.3, 0.5), which also scales the offset.
    const glm::dvec3 blend(0.2, 0.3, 0.5), unit = glm::normalize(blend);
    EXPECT_NEAR(r->dir.x, unit.x, 1e-12);
    EXPECT_NEAR(r->dir.y, unit.y, 1e-12);
    EXPECT_NEAR(r->dir.z, unit.z, 1e-12);
    EXPECT_NEAR(r->origin.x, 0.4 + blend.x, 1e-12);
    EXPECT_NEAR(r->origin.y, 0.6 + blend.y, 1e-12);
    EXPECT_NEAR(r->origin.z, blend.z, 1e-12);
    // Reversed and moved with the mesh.
    scene::Camera c = uv_camera(uv_mesh({kLowerLeft}, normals), 0, true);
    c.mesh->reverse = true;
    auto moved = std::make_shared<scene::Object>(*c.mesh->meshes[0]);
    moved->transform = {glm::dmat4(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 0, 0, 1),
                        glm::dmat4(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -5, 0, 0, 1)};
    c.mesh->meshes = {moved};
    const auto back = CameraModel(c, 10, 10).ray(2, 7);
    EXPECT_NEAR(back->origin.x, 5.4, 1e-12);
    EXPECT_NEAR(back->dir.z, -unit.z, 1e-12);
}

TEST(Camera, MeshCameraUvCellsFindTheSameFaceAsASearchInMeshOrder) {
    // Many overlapping random uv triangles, some reaching past the unit square, some slivers:
    // the cell lookup must return the first containing face, as a plain search does.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> at(-0.05, 1.05), size(0.001, 0.3);
    std::vector<UvFace> faces;
    for (int i = 0; i < 3000; ++i) {
        const glm::dvec2 a(at(rng), at(rng));
        UvFace f;
        f.uv = {a, a + glm::dvec2(size(rng), size(rng) * 0.2), a + glm::dvec2(size(rng) * 0.3, size(rng))};
        f.p = {glm::dvec3(3 * i, 0, 0), glm::dvec3(3 * i, 1, 0), glm::dvec3(3 * i + 1, 0, 0)};
        faces.push_back(f);
    }
    const CameraModel cam(uv_camera(uv_mesh(faces), 0, false), 97, 89);
    int found = 0;
    for (int j = 0; j < 89; ++j)
        for (int i = 0; i < 97; ++i) {
            const double u = std::clamp(i + 0.5, 0.0, 96.0) - 0.5, v = std::clamp(j - 0.5, 0.0, 88.0) + 0.5;
            const double su = u / 97, sv = 1 - v / 89;
            int first = -1;
            for (size_t f = 0; f < faces.size() && first < 0; ++f) {
                const auto& p = faces[f].uv;
                const double s = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
                const double b0 = ((p[1].x - su) * (p[2].y - sv) - (p[2].x - su) * (p[1].y - sv)) / s;
                const double b1 = ((p[2].x - su) * (p[0].y - sv) - (p[0].x - su) * (p[2].y - sv)) / s;
                const double b2 = ((p[0].x - su) * (p[1].y - sv) - (p[1].x - su) * (p[0].y - sv)) / s;
                if (b0 >= 0 && b1 >= 0 && b2 >= 0) first = int(f);
            }
            const auto r = cam.ray(i, j);
            ASSERT_EQ(r.has_value(), first >= 0) << i << " " << j;
            if (first < 0) continue;
            ++found;
            // Face f's corners have x in [3f, 3f + 1].
            EXPECT_GE(r->origin.x, 3 * first - 1e-9) << i << " " << j;
            EXPECT_LE(r->origin.x, 3 * first + 1 + 1e-9) << i << " " << j;
        }
    EXPECT_GT(found, 97 * 89 / 2);
}

}  // namespace
}  // namespace lumen::render
