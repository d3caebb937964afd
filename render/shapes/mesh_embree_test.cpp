// Meshes traced through Embree (mesh_embree.hpp) answer as lumen's own BVH does: the same
// hits, distances, shadow tests and insides, also where single precision is coarse (a mesh far
// from its origin) and for rays that leave the surface.
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "render/shapes/mesh.hpp"

namespace lumen::render {
namespace {

// A closed, bumpy sphere of about 2 * rings * segments triangles about `centre`.
scene::Mesh bumpy_sphere(const glm::dvec3& centre, int rings, int segments) {
    scene::Mesh m;
    const double pi = std::numbers::pi;
    m.vertices.push_back(centre + glm::dvec3(0, 1, 0));
    for (int i = 1; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            const double th = pi * i / rings, ph = 2 * pi * j / segments;
            const double r = 1 + 0.1 * std::sin(5 * th) * std::cos(7 * ph);
            m.vertices.push_back(centre + r * glm::dvec3(std::sin(th) * std::cos(ph), std::cos(th),
                                                         std::sin(th) * std::sin(ph)));
        }
    m.vertices.push_back(centre + glm::dvec3(0, -1, 0));
    const int south = int(m.vertices.size()) - 1;
    auto at = [&](int ring, int j) { return 1 + (ring - 1) * segments + (j % segments); };
    auto face = [&](int a, int b, int c) {
        scene::Mesh::Face f;
        f.v = {a, b, c};
        m.faces.push_back(f);
    };
    for (int j = 0; j < segments; ++j) {
        face(0, at(1, j), at(1, j + 1));
        face(south, at(rings - 1, j + 1), at(rings - 1, j));
        for (int i = 1; i + 1 < rings; ++i) {
            face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
            face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
        }
    }
    m.inside_vector = glm::dvec3(0.3, 1, 0.2);
    return m;
}

glm::dvec3 random_unit(std::mt19937& rng) {
    std::normal_distribution<double> n(0, 1);
    glm::dvec3 d(n(rng), n(rng), n(rng));
    return d / std::sqrt(glm::dot(d, d));
}

struct Agreement {
    int rays = 0, hit_mismatch = 0, far_t = 0, any_mismatch = 0, inside_mismatch = 0;
};

// Casts rays from outside, from inside and from the surface itself through both tracers.
Agreement compare(const scene::Mesh& m, const glm::dvec3& centre, unsigned seed) {
    const auto embree = make_mesh(m, MeshTraversal::Best);
    const auto own = make_mesh(m, MeshTraversal::Bvh);
    EXPECT_TRUE(embree->embree);
    EXPECT_FALSE(own->embree);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    Agreement a;
    auto one = [&](const LocalRay& r, double tmin) {
        ++a.rays;
        ShapeHit he, ho;
        const bool e = intersect(*embree, r, tmin, 1e30, he), o = intersect(*own, r, tmin, 1e30, ho);
        if (e != o) ++a.hit_mismatch;
        else if (e && std::abs(he.t - ho.t) > 1e-9 * std::max(1.0, ho.t)) ++a.far_t;
        double te, to;
        if (any_hit(*embree, r, tmin, 1e30, te) != any_hit(*own, r, tmin, 1e30, to)) ++a.any_mismatch;
        return o ? r.at(ho.t) : glm::dvec3(0);
    };
    for (int i = 0; i < 4000; ++i) {
        const glm::dvec3 p = centre + glm::dvec3(u(rng), u(rng), u(rng));
        // From a random point (outside or inside), then on from the surface it reaches.
        const glm::dvec3 on = one({p, random_unit(rng)}, 1e-6);
        if (on != glm::dvec3(0)) one({on, random_unit(rng)}, 1e-6);
        if (inside(*embree, p) != inside(*own, p)) ++a.inside_mismatch;
    }
    return a;
}

TEST(MeshEmbree, BigMeshesOnly) {
    if (!EmbreeMesh::built_in()) GTEST_SKIP() << "lumen is built without Embree";
    EXPECT_TRUE(make_mesh(bumpy_sphere({0, 0, 0}, 40, 40))->embree);
    EXPECT_FALSE(make_mesh(bumpy_sphere({0, 0, 0}, 4, 4))->embree);  // 32 triangles
    EXPECT_FALSE(make_mesh(bumpy_sphere({0, 0, 0}, 40, 40), MeshTraversal::Scan)->embree);
    // Beyond single precision's range Embree cannot hold the vertices.
    EXPECT_FALSE(make_mesh(bumpy_sphere({1e39, 0, 0}, 40, 40))->embree);
}

// Near the origin, and far from it, where single precision's steps (about 1e-3 at 1e4) would
// dwarf tmin but for the mesh's own centre: a ray leaving the surface may meet its own
// triangle in Embree, and the plane's double-precision distance must turn it down. Only rays
// within rounding of an edge may choose differently.
TEST(MeshEmbree, AgreesWithOwnBvh) {
    if (!EmbreeMesh::built_in()) GTEST_SKIP() << "lumen is built without Embree";
    unsigned seed = 1;
    for (const glm::dvec3 c : {glm::dvec3(0), glm::dvec3(1.25e4, -3e3, 7e3)}) {
        const Agreement a = compare(bumpy_sphere(c, 60, 80), c, seed++);
        EXPECT_GT(a.rays, 5000);
        EXPECT_LE(a.hit_mismatch, a.rays / 1000) << "centre " << c.x;
        EXPECT_LE(a.far_t, a.rays / 1000) << "centre " << c.x;
        EXPECT_LE(a.any_mismatch, a.rays / 1000) << "centre " << c.x;
        EXPECT_LE(a.inside_mismatch, 4) << "centre " << c.x;
    }
}

// Rays aimed at a grid's shared edges, far from the origin, all meet it: Embree's choice of
// triangle within rounding of an edge is taken, not turned down. Rays aimed exactly at a
// vertex may still slip through (Embree's robust mode is watertight along edges, not at every
// vertex): a few in a thousand of them, which a render meets at single points.
TEST(MeshEmbree, NoCracksAlongEdges) {
    if (!EmbreeMesh::built_in()) GTEST_SKIP() << "lumen is built without Embree";
    const glm::dvec3 c(3e4, 1e3, -2e4);
    const int n = 48;
    scene::Mesh m;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) m.vertices.push_back(c + glm::dvec3(i * 0.37, j * 0.37, 0));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int a = j * (n + 1) + i, b = a + 1, d = a + n + 1, e = d + 1;
            scene::Mesh::Face f1, f2;
            f1.v = {a, b, e};
            f2.v = {a, e, d};
            m.faces.push_back(f1);
            m.faces.push_back(f2);
        }
    const auto s = make_mesh(m);
    ASSERT_TRUE(s->embree);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-20, 20);
    int misses = 0, vertex_misses = 0, wrong_t = 0, rays = 0;
    for (int j = 1; j < 2 * n; ++j)
        for (int i = 1; i < 2 * n; ++i) {
            // Vertices, edge midpoints and quad centres (on the diagonals).
            const glm::dvec3 target = c + glm::dvec3(i * 0.185, j * 0.185, 0);
            const glm::dvec3 from = target + glm::dvec3(u(rng), u(rng), 10 + std::abs(u(rng)));
            const LocalRay r{from, target - from};  // t = 1 at the target
            ShapeHit h;
            ++rays;
            const bool vertex = i % 2 == 0 && j % 2 == 0;
            if (!intersect(*s, r, 1e-6, 1e30, h)) ++(vertex ? vertex_misses : misses);
            else if (std::abs(h.t - 1) > 1e-9) ++wrong_t;
        }
    EXPECT_EQ(misses, 0) << "of " << rays;
    EXPECT_LE(vertex_misses, rays / 4 / 100);
    EXPECT_EQ(wrong_t, 0);
}

TEST(MeshEmbree, NonFiniteRaysMiss) {
    if (!EmbreeMesh::built_in()) GTEST_SKIP() << "lumen is built without Embree";
    const scene::Mesh m = bumpy_sphere({0, 0, 0}, 40, 40);  // the shape points into it
    const auto s = make_mesh(m);
    ShapeHit h;
    double t;
    EXPECT_FALSE(intersect(*s, {{NAN, 0, -5}, {0, 0, 1}}, 1e-6, 1e30, h));
    EXPECT_FALSE(any_hit(*s, {{0, 0, -5}, {0, INFINITY, 1}}, 1e-6, 1e30, t));
    EXPECT_TRUE(intersect(*s, {{0, 0, -5}, {0, 0, 1}}, 1e-6, INFINITY, h));
    EXPECT_NEAR(h.t, 4, 0.2);
}

}  // namespace
}  // namespace lumen::render
