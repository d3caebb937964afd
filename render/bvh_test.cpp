// The BVH against brute force, and mesh performance.
#include <chrono>
#include <cmath>
#include <random>
#include <thread>

#include <gtest/gtest.h>

#include "render/bvh.hpp"
#include "render/wide_bvh.hpp"
#include "render/geometry_test_util.hpp"

namespace lumen::render {
namespace {

using namespace testing;

// `count` boxes of sizes 0.02 to 2 scattered over [-10, 10]^3.
std::vector<Aabb> random_boxes(std::mt19937& rng, int count) {
    std::uniform_real_distribution<double> u(-10, 10), s(0.01, 1);
    std::vector<Aabb> boxes;
    for (int i = 0; i < count; ++i) {
        glm::dvec3 c{u(rng), u(rng), u(rng)};
        boxes.push_back({c - s(rng), c + s(rng)});
    }
    return boxes;
}

Bvh built(const std::vector<Aabb>& boxes) {
    Bvh bvh;
    bvh.build(boxes, 4);
    return bvh;
}

TEST(Bvh, VisitsEveryBoxTheRayMeets) {
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(-10, 10);
    const std::vector<Aabb> boxes = random_boxes(rng, 2000);
    const Bvh bvh = built(boxes);
    EXPECT_LT(bvh.depth(), 40);
    for (int r = 0; r < 300; ++r) {
        glm::dvec3 o{u(rng), u(rng), u(rng)}, d = glm::normalize(glm::dvec3{u(rng), u(rng), u(rng)});
        if (r % 10 == 0) d = {0, 0, 1};  // zero components
        SlabRay slab(o, d);
        std::vector<char> seen(boxes.size(), 0);
        double tmax = 1e30;
        bvh.traverse(slab, 0, tmax, [&](uint32_t i) { seen[bvh.order()[i]] = 1; });
        size_t visited = 0;
        for (size_t i = 0; i < boxes.size(); ++i) {
            if (slab.hits(boxes[i], 0, 1e30)) { EXPECT_TRUE(seen[i]) << r << " " << i; }
            visited += seen[i];
        }
        EXPECT_LT(visited, boxes.size() / 4);  // culling works
    }
}

TEST(Bvh, WideFormVisitsTheLeavesTheBinaryOneVisits) {
    // Without pruning (tmax stays), both visit every leaf whose boxes the ray meets: the same
    // set, as the four-wide slab test is the binary one lane by lane. With a nearest-hit
    // search both find the same nearest box entry.
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-10, 10);
    const std::vector<Aabb> boxes = random_boxes(rng, 3000);
    const Bvh bvh = built(boxes);
    const WideBvh wide(bvh);
    EXPECT_LT(wide.node_count(), bvh.nodes().size() / 2);
    for (int r = 0; r < 500; ++r) {
        glm::dvec3 o{u(rng), u(rng), u(rng)}, d = glm::normalize(glm::dvec3{u(rng), u(rng), u(rng)});
        if (r % 10 == 0) d = {0, 0, 1};  // zero components
        if (r % 10 == 1) d = {0, -1, 0};
        const SlabRay slab(o, d);
        std::vector<char> binary(boxes.size(), 0), wide_seen(boxes.size(), 0);
        double tmax = 1e30;
        bvh.traverse(slab, 0, tmax, [&](uint32_t i) { binary[i] = 1; });
        wide.traverse(slab, 0, tmax, [&](uint32_t i) { wide_seen[i] += 1; });
        ASSERT_EQ(binary, wide_seen) << r;  // and none twice
        double nearest_binary = 1e30, nearest_wide = 1e30;
        auto nearest = [&](double& best) {
            return [&](uint32_t i) {
                double enter, exit;
                if (slab.hits(boxes[bvh.order()[i]], 0, best, enter, exit)) best = enter;
            };
        };
        bvh.traverse(slab, 0, nearest_binary, nearest(nearest_binary));
        wide.traverse(slab, 0, nearest_wide, nearest(nearest_wide));
        ASSERT_EQ(nearest_binary, nearest_wide) << r;
    }
}

// Nearest sphere by testing each one directly.
double brute_nearest(const std::vector<scene::Sphere>& spheres, const Ray& r, int& which) {
    double best = 1e30;
    which = -1;
    for (size_t i = 0; i < spheres.size(); ++i) {
        glm::dvec3 oc = r.origin - spheres[i].center;
        double b = glm::dot(oc, r.dir), c = glm::dot(oc, oc) - spheres[i].radius * spheres[i].radius;
        double disc = b * b - c;
        if (disc < 0) continue;
        for (double t : {-b - std::sqrt(disc), -b + std::sqrt(disc)}) {
            if (t > 1e-4 && t < best) {
                best = t;
                which = int(i);
                break;
            }
        }
    }
    return best;
}

TEST(Bvh, ThousandRandomSpheresMatchBruteForce) {
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> u(-20, 20), rad(0.1, 1.5);
    std::vector<scene::Sphere> spheres;
    std::vector<scene::ObjectPtr> objects;
    for (int i = 0; i < 1000; ++i) {
        spheres.push_back({{u(rng), u(rng), u(rng)}, rad(rng)});
        objects.push_back(make(spheres.back()));
    }
    Geometry g(scene_of(objects));
    EXPECT_EQ(g.primitive_count(), 1000u);
    int hits = 0;
    for (int r = 0; r < 3000; ++r) {
        Ray rr = ray({u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)});
        int which;
        double expect = brute_nearest(spheres, rr, which);
        auto h = trace(g, rr);
        ASSERT_EQ(bool(h), which >= 0) << r;
        if (!h) continue;
        ++hits;
        EXPECT_NEAR(h->t, expect, 1e-9 * (1 + expect));
        EXPECT_EQ(h->object, objects[which].get());
    }
    EXPECT_GT(hits, 1000);
}

TEST(Bvh, ConcurrentQueriesAgreeWithSerialOnes) {
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> u(-5, 5);
    std::vector<scene::ObjectPtr> objects;
    for (int i = 0; i < 200; ++i)
        objects.push_back(make(scene::Torus{0.5, 0.2, false}, translate({u(rng), u(rng), u(rng)})));
    auto merged = csg(scene::CsgOp::Merge, {make(scene::Sphere{{0, 0, 0}, 2}),
                                            make(scene::Box{{0, 0, 0}, {3, 3, 3}})});
    objects.push_back(merged);
    Geometry g(scene_of(objects));
    std::vector<Ray> rays;
    for (int i = 0; i < 4000; ++i) rays.push_back(ray({u(rng), u(rng), -10}, {u(rng) * 0.1, u(rng) * 0.1, 1}));
    std::vector<double> serial(rays.size(), -1), parallel(rays.size(), -1);
    for (size_t i = 0; i < rays.size(); ++i)
        if (auto h = trace(g, rays[i])) serial[i] = h->t;
    std::vector<std::thread> threads;
    for (int k = 0; k < 4; ++k)
        threads.emplace_back([&, k] {
            for (size_t i = k; i < rays.size(); i += 4)
                if (auto h = trace(g, rays[i])) parallel[i] = h->t;
        });
    for (auto& t : threads) t.join();
    EXPECT_EQ(serial, parallel);
}

TEST(Bvh, HundredThousandTriangleMeshIsFast) {
    // A bumpy height field of 224 x 224 quads = 100352 triangles.
    const int n = 224;
    scene::Mesh m;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            double x = double(i) / n * 10 - 5, z = double(j) / n * 10 - 5;
            m.vertices.push_back({x, 0.3 * std::sin(3 * x) * std::cos(2 * z), z});
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            m.faces.push_back({{a, b, d}});
            m.faces.push_back({{a, d, c}});
        }
    auto start = std::chrono::steady_clock::now();
    Geometry g(scene_of({make(m)}));
    double build = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(g.primitive_count(), 100352u);

    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-4.5, 4.5);
    const int rays = 100000;
    int hits = 0;
    start = std::chrono::steady_clock::now();
    for (int r = 0; r < rays; ++r) {
        Ray rr = ray({0.7 * u(rng), 3, 0.7 * u(rng)}, {u(rng) * 0.1, -1, u(rng) * 0.1});
        Hit h;
        if (g.intersect(rr, 1e-4, 1e30, h)) {
            ++hits;
            // The hit lies on the height field (within its linear interpolation error).
            double fx = 0.3 * std::sin(3 * h.point.x) * std::cos(2 * h.point.z);
            EXPECT_NEAR(h.point.y, fx, 0.01);
        }
    }
    double trace_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(hits, rays);
    // Generous bounds (the test machine may be busy): a linear scan per ray would take
    // minutes, ~log n per ray takes well under a second.
    EXPECT_LT(build, 5.0);
    EXPECT_LT(trace_s, 5.0);
    std::printf("100k-triangle mesh: build %.3f s, %d rays %.3f s\n", build, rays, trace_s);
}

TEST(Bvh, MeshShadowRaysAgreeWithNearestHits) {
    // Two wavy layers of triangles, 0.5 apart: a shadow ray (occluded(), which takes the
    // first triangle it meets) is blocked exactly when a nearest-hit search finds one within
    // its length, whether it ends above both layers, between them or below.
    const int n = 40;
    scene::Mesh m;
    for (int layer = 0; layer < 2; ++layer)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                double x = double(i) / n * 4 - 2, z = double(j) / n * 4 - 2;
                m.vertices.push_back({x, 0.2 * std::sin(3 * x + z) - 0.5 * layer, z});
            }
    const int per_layer = (n + 1) * (n + 1);
    for (int layer = 0; layer < 2; ++layer)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                int a = layer * per_layer + j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
                m.faces.push_back({{a, b, d}});
                m.faces.push_back({{a, d, c}});
            }
    Geometry g(scene_of({make(m)}));
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> u(-1.5, 1.5), len(0.1, 4);
    int blocked = 0;
    for (int r = 0; r < 20000; ++r) {
        const Ray rr = ray({u(rng), 1, u(rng)}, {u(rng) * 0.2, -1, u(rng) * 0.2});
        const double tmax = len(rng);
        Hit h;
        const bool nearest = g.intersect(rr, 1e-4, tmax, h);
        ASSERT_EQ(g.occluded(rr, 1e-4, tmax, Query::Shadow), nearest) << r;
        blocked += nearest;
    }
    EXPECT_GT(blocked, 5000);
    EXPECT_LT(blocked, 19000);
}

}  // namespace
}  // namespace lumen::render
