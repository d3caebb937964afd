// Meshing primitives into patches: areas, orientation, edge lengths, transforms, clipping.
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "render/radiosity/ff_matrix.hpp"
#include "render/radiosity/mesher.hpp"
#include "render/radiosity/radiosity_test_util.hpp"

namespace lumen::render::radiosity {
namespace {

constexpr double pi = std::numbers::pi;

scene::Object object(scene::Shape shape, glm::dmat4 m = glm::dmat4(1.0)) {
    scene::Object o;
    o.shape = std::move(shape);
    o.transform = {m, glm::inverse(m)};
    return o;
}

std::vector<Patch> mesh(const scene::Object& o, double edge, bool inward = false) {
    MeshOptions opt;
    opt.max_edge = edge;
    opt.inward = inward;
    opt.bounds_min = glm::dvec3(-1);
    opt.bounds_max = glm::dvec3(1);
    return mesh_object(o, opt, {glm::dvec3(0.5), glm::dvec3(0), 4});
}

// Every patch faces away from `centre` (or toward it when `inward`).
void expect_facing(const std::vector<Patch>& patches, glm::dvec3 centre, bool outward = true) {
    for (const auto& p : patches) {
        const double d = glm::dot(p.normal, p.centroid - centre);
        EXPECT_TRUE(outward ? d > 0 : d < 0) << "centroid " << p.centroid.x << ","
                                             << p.centroid.y << "," << p.centroid.z;
    }
}

double longest_edge(const std::vector<Patch>& patches) {
    double m = 0;
    for (const auto& p : patches)
        for (size_t i = 0; i < p.vertices.size(); ++i)
            m = std::max(m, glm::length(p.vertices[(i + 1) % p.vertices.size()] - p.vertices[i]));
    return m;
}

TEST(Mesher, BoxAreaOrientationAndEdges) {
    const auto box = object(scene::Box{{1, 0, 0}, {-1, 2, 3}});  // corners in any order
    const auto patches = mesh(box, 0.5);
    EXPECT_NEAR(total_area(patches), 2 * (2 * 2 + 2 * 3 + 2 * 3), 1e-9);
    EXPECT_LE(longest_edge(patches), 0.5 + 1e-9);
    expect_facing(patches, {0, 1, 1.5});
    expect_facing(mesh(box, 0.5, true), {0, 1, 1.5}, false);
    for (const auto& p : patches) {
        EXPECT_EQ(p.object, 4);
        EXPECT_EQ(p.rho, glm::dvec3(0.5));
    }
}

TEST(Mesher, TransformsIncludingMirrors) {
    const glm::dmat4 m = glm::translate(glm::dmat4(1.0), glm::dvec3(5, 0, 0)) *
                         glm::scale(glm::dmat4(1.0), glm::dvec3(-2, 2, 2));  // mirrored
    const auto patches = mesh(object(scene::Box{{-1, -1, -1}, {1, 1, 1}}, m), 1.0);
    EXPECT_NEAR(total_area(patches), 6 * 16, 1e-9);
    EXPECT_LE(longest_edge(patches), 1.0 + 1e-9);
    expect_facing(patches, {5, 0, 0});
}

TEST(Mesher, SphereConvergesToTheTrueArea) {
    const auto coarse = mesh(object(scene::Sphere{{1, 2, 3}, 2}), 1.0);
    const auto fine = mesh(object(scene::Sphere{{1, 2, 3}, 2}), 0.1);
    const double exact = 4 * pi * 4;
    EXPECT_LT(std::abs(total_area(fine) - exact), std::abs(total_area(coarse) - exact));
    EXPECT_NEAR(total_area(fine), exact, 0.01 * exact);
    EXPECT_LE(longest_edge(fine), 0.1 * 1.01);
    expect_facing(coarse, {1, 2, 3});
    expect_facing(mesh(object(scene::Sphere{{1, 2, 3}, 2}), 1.0, true), {1, 2, 3}, false);
}

TEST(Mesher, QuadricsAndTorus) {
    const auto cyl = mesh(object(scene::Cylinder{{0, 0, 0}, {0, 2, 0}, 0.5, false}), 0.05);
    EXPECT_NEAR(total_area(cyl), 2 * pi * 0.5 * 2 + 2 * pi * 0.25, 0.01 * 2.5 * pi);
    expect_facing(cyl, {0, 1, 0});
    const auto open = mesh(object(scene::Cylinder{{0, 0, 0}, {0, 2, 0}, 0.5, true}), 0.05);
    EXPECT_NEAR(total_area(open), 2 * pi * 0.5 * 2, 0.01 * 2 * pi);
    const auto cone = mesh(object(scene::Cone{{0, 0, 0}, 1, {0, 1, 0}, 0, false}), 0.05);
    EXPECT_NEAR(total_area(cone), pi * std::sqrt(2.0) + pi, 0.01 * 2.4 * pi);
    expect_facing(cone, {0, 0.3, 0});
    const auto disc = mesh(object(scene::Disc{{0, 1, 0}, {0, 0, 1}, 1, 0.5}), 0.05);
    EXPECT_NEAR(total_area(disc), pi * 0.75, 0.01 * pi);
    for (const auto& p : disc) EXPECT_NEAR(p.normal.z, 1.0, 1e-12);
    const auto torus = mesh(object(scene::Torus{2, 0.5, false}), 0.05);
    EXPECT_NEAR(total_area(torus), 4 * pi * pi * 2 * 0.5, 0.01 * 4 * pi * pi);
    for (const auto& p : torus) {  // outward from the tube's core circle
        const glm::dvec3 c = p.centroid;
        const glm::dvec3 core = 2.0 * glm::normalize(glm::dvec3(c.x, 0, c.z));
        EXPECT_GT(glm::dot(p.normal, c - core), 0);
    }
}

TEST(Mesher, AStretchAlongTheAxisDoesNotMultiplyTheCircles) {
    // A disc-like cylinder (radius 4, length 1 along z) scaled 1000 along z: its circles
    // stay as they were, only the length is split (patio-radio_36.pov's balconies).
    const glm::dmat4 stretch = glm::scale(glm::dmat4(1.0), glm::dvec3(1, 1, 1000));
    const auto plain = mesh(object(scene::Cylinder{{0, 0, 0}, {0, 0, 1}, 4, false}), 10);
    const auto long_one = mesh(object(scene::Cylinder{{0, 0, 0}, {0, 0, 1}, 4, false}, stretch), 10);
    // min_segments (8) chords around: 2.6% short of the true circumference.
    EXPECT_NEAR(total_area(long_one), 2 * pi * 4 * 1000 + 2 * pi * 16, 0.03 * 2 * pi * 4 * 1000);
    EXPECT_LE(longest_edge(long_one), 10 * 1.01);
    // The lateral surface needs 100 rows of 10; the caps need nothing more than unscaled.
    EXPECT_LT(long_one.size(), plain.size() + 100 * 2 * 16);
    // A uniform scale still refines everything.
    const auto big = mesh(object(scene::Cylinder{{0, 0, 0}, {0, 0, 1}, 4, false},
                                 glm::scale(glm::dmat4(1.0), glm::dvec3(10))), 10);
    EXPECT_LE(longest_edge(big), 10 * 1.01);
}

TEST(Mesher, PlaneClippedToTheBounds) {
    const auto floor = mesh(object(scene::Plane{{0, 1, 0}, 0.25}), 0.3);
    EXPECT_NEAR(total_area(floor), 4.0, 1e-9);
    for (const auto& p : floor) {
        EXPECT_NEAR(p.normal.y, 1.0, 1e-12);
        EXPECT_NEAR(p.centroid.y, 0.25, 1e-12);
    }
    // A tilted plane cuts the cube [-1,1]^3 in a hexagon of area 3√3 (through the centre).
    const auto tilted = mesh(object(scene::Plane{glm::normalize(glm::dvec3(1, 1, 1)), 0}), 0.2);
    EXPECT_NEAR(total_area(tilted), 3 * std::sqrt(3.0), 1e-9);
    EXPECT_TRUE(mesh(object(scene::Plane{{0, 1, 0}, 5}), 0.3).empty());  // outside the bounds
    // Cutting off one corner of the cube: a triangle with legs 0.5 (area √3/8), away from the
    // cube's centre.
    const auto corner =
        mesh(object(scene::Plane{glm::normalize(glm::dvec3(1, 1, 1)), 2.5 / std::sqrt(3.0)}), 0.1);
    EXPECT_NEAR(total_area(corner), std::sqrt(3.0) / 8, 1e-9);
}

TEST(Mesher, TrianglePolygonAndMesh) {
    const auto tri = mesh(object(scene::Triangle{{glm::dvec3(0, 0, 0), {4, 0, 0}, {0, 3, 0}}}), 0.5);
    EXPECT_NEAR(total_area(tri), 6.0, 1e-9);
    EXPECT_LE(longest_edge(tri), 0.5 + 1e-9);
    // Non-convex L shape (area 3), closed as POV writes it, then a second square (area 1).
    scene::Polygon poly{{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0},
                         {0, 0, 0}, {5, 0, 0}, {6, 0, 0}, {6, 1, 0}, {5, 1, 0}, {5, 0, 0}}};
    const auto lshape = mesh(object(poly), 10);
    EXPECT_NEAR(total_area(lshape), 4.0, 1e-9);
    for (const auto& p : lshape) EXPECT_NEAR(p.normal.z, 1.0, 1e-12);
    scene::Mesh m;
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    auto& faces = m.faces.edit();
    faces.resize(3);
    faces[0].v = {0, 1, 2};
    faces[1].v = {0, 2, 3};
    faces[2].v = {0, 2, 99};  // bad index: skipped
    EXPECT_NEAR(total_area(mesh(object(m), 0.25)), 1.0, 1e-9);
}

TEST(Mesher, CsgIsNotMeshed) {
    const auto csg = object(scene::Csg{});
    EXPECT_FALSE(meshable(csg));
    EXPECT_TRUE(mesh(csg, 1).empty());
    EXPECT_TRUE(meshable(object(scene::Box{})));
}

TEST(Mesher, MeshedEnclosureIsClosedForFormFactors) {
    // A box meshed from the inside: every row of the analytic matrix sums to 1.
    const auto patches = mesh(object(scene::Box{{0, 0, 0}, {2, 1, 1}}), 0.5, true);
    const auto F = analytic_matrix(patches, {3, 2});
    for (size_t i = 0; i < F.n; i += 7) EXPECT_NEAR(F.row_sum(i), 1.0, 1e-5) << i;
}

TEST(Subdivide, PreservesAreaAndMaterial) {
    Patch p = testing::floor_rect(3, 1);
    p.rho = glm::dvec3(0.1, 0.2, 0.3);
    p.emission = glm::dvec3(2);
    const auto parts = subdivide(p, 0.5);
    EXPECT_EQ(parts.size(), 12u);
    EXPECT_NEAR(total_area(parts), 3.0, 1e-12);
    for (const auto& e : parts) {
        EXPECT_EQ(e.rho, p.rho);
        EXPECT_EQ(e.emission, p.emission);
        EXPECT_NEAR(e.normal.z, 1.0, 1e-12);
    }
    const Patch pent = make_patch({{0, 0, 0}, {2, 0, 0}, {3, 1, 0}, {1, 2, 0}, {-1, 1, 0}});
    EXPECT_NEAR(total_area(subdivide(pent, 0.4)), pent.area, 1e-12);
    EXPECT_EQ(subdivide(p, 0).size(), 1u);
}

TEST(PatchGeometry, SamplingAndIntersection) {
    const Patch p = make_patch({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}});
    EXPECT_NEAR(p.area, 2.0, 1e-12);
    EXPECT_NEAR(p.centroid.x, 1.0, 1e-12);
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(0, 1);
    double mean_x = 0;
    for (int k = 0; k < 20000; ++k) {
        const glm::dvec3 x = sample_point(p, u(rng), u(rng));
        ASSERT_TRUE(x.x >= 0 && x.x <= 2 && x.y >= 0 && x.y <= 1 && x.z == 0);
        mean_x += x.x / 20000;
    }
    EXPECT_NEAR(mean_x, 1.0, 0.02);
    EXPECT_NEAR(intersect(p, {1, 0.5, 3}, {0, 0, -1}), 3.0, 1e-12);
    EXPECT_LT(intersect(p, {3, 0.5, 3}, {0, 0, -1}), 0);
    EXPECT_LT(intersect(p, {1, 0.5, 3}, {0, 0, 1}), 0);  // behind the origin
    EXPECT_NEAR(intersect(p, {2, 1, 1}, {0, 0, -1}), 1.0, 1e-12);  // a corner counts
}

}  // namespace
}  // namespace lumen::render::radiosity
