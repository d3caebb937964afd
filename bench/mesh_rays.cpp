// Mesh rays per second per core, in millions: lumen (render::Geometry, the renderer's own
// intersect() and occluded()) against Embree 3 called directly (libembree-dev; rtcIntersect1 /
// rtcOccluded1, one ray at a time as lumen traces them), at its defaults and in its robust
// mode (watertight along edges, as lumen's meshes need), on the same triangles and rays, one
// thread each. The ratios are Embree's rate over lumen's.
//
// The mesh is a bumpy height-field grid of about T triangles (default 200k and 2M), seen by a
// camera from above and aside. Primary rays: one per pixel of a 1024x768 view. Shadow rays:
// from each primary hit towards a point light (any hit). Diffuse rays: from each primary hit,
// one cosine-distributed direction about the normal (nearest hit). Each kind is timed alone,
// the tracers in turn over five rounds (medians printed); the hit counts are printed as a
// check that they saw the same scene. Where lumen is built with Embree, its big meshes trace
// through Embree's robust BVH (render/shapes/mesh_embree.hpp), so the ratio to the robust
// column is the cost of lumen's side: its object tree, the double-precision distance to the
// triangle met and the hit record.
//
// Usage: build/bench/mesh_rays [TRIANGLES ...]   (without Embree: lumen's figures only)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "render/geometry.hpp"
#include "scene/scene.hpp"

#ifdef LUMEN_HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

namespace {

using namespace lumen;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

scene::Mesh grid_mesh(long triangles) {
    const int n = std::max(2, int(std::sqrt(double(triangles) / 2) + 0.5)), m = n + 1;
    scene::Mesh mesh;
    mesh.vertices.edit().reserve(size_t(m) * m);
    for (int j = 0; j < m; ++j)
        for (int i = 0; i < m; ++i) {
            const double x = double(i) / n, z = double(j) / n;
            const double y = 0.08 * std::sin(x * 37.0 + 3 * std::sin(z * 11.0)) * std::cos(z * 29.0) +
                             0.15 * std::sin(x * 5.0) * std::sin(z * 4.0);
            mesh.vertices.push_back({x, y, z});
        }
    mesh.faces.edit().reserve(size_t(2) * n * n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int a = j * m + i, b = a + 1, c = a + m, d = c + 1;
            scene::Mesh::Face f1, f2;
            f1.v = {a, b, d};
            f2.v = {a, d, c};
            mesh.faces.push_back(f1);
            mesh.faces.push_back(f2);
        }
    return mesh;
}

struct Rays {
    std::vector<render::Ray> primary, shadow, diffuse;
    std::vector<double> shadow_length;
};

// Primary rays from lumen's answers; the shadow and diffuse rays start at its hits.
Rays make_rays(const render::Geometry& g) {
    Rays rays;
    const glm::dvec3 eye{0.5, 0.9, -0.45}, look{0.5, 0, 0.45}, light{2, 4, -1};
    const glm::dvec3 w = glm::normalize(look - eye), u = glm::normalize(glm::cross(glm::dvec3(0, 1, 0), w)),
                     v = glm::cross(w, u);
    const int W = 1024, H = 768;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u01(0, 1);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const double px = (x + 0.5) / W * 2 - 1, py = 1 - (y + 0.5) / H * 2;
            const render::Ray r{eye, glm::normalize(w + 0.45 * px * u + 0.45 * 0.75 * py * v)};
            rays.primary.push_back(r);
            render::Hit h;
            if (!g.intersect(r, 1e-6, 1e30, h)) continue;
            const glm::dvec3 n = glm::dot(h.normal, r.dir) > 0 ? -h.normal : h.normal;
            const glm::dvec3 to_light = light - h.point;
            rays.shadow.push_back({h.point, glm::normalize(to_light)});
            rays.shadow_length.push_back(glm::length(to_light));
            // Cosine-distributed about n.
            const double a = 2 * std::numbers::pi * u01(rng), r2 = u01(rng), s = std::sqrt(r2);
            const glm::dvec3 t = glm::normalize(std::abs(n.x) < 0.9 ? glm::cross(n, glm::dvec3(1, 0, 0))
                                                                    : glm::cross(n, glm::dvec3(0, 1, 0)));
            const glm::dvec3 b = glm::cross(n, t);
            rays.diffuse.push_back(
                {h.point, glm::normalize(s * std::cos(a) * t + s * std::sin(a) * b + std::sqrt(1 - r2) * n)});
        }
    return rays;
}

struct Figure {
    double rays_per_s = 0;
    long hits = 0;
};

constexpr int kRounds = 5;

// Runs `trace` over the rays until at least 0.3 s has passed; rays per second and hits.
template <class Trace> Figure timed(size_t count, const Trace& trace) {
    Figure f;
    long done = 0;
    const auto start = Clock::now();
    do {
        long hits = 0;
        for (size_t i = 0; i < count; ++i) hits += trace(i);
        f.hits = hits;
        done += long(count);
    } while (seconds_since(start) < 0.3);
    f.rays_per_s = double(done) / seconds_since(start);
    return f;
}

Figure median(std::vector<Figure> runs) {
    if (runs.empty()) return {};
    std::sort(runs.begin(), runs.end(),
              [](const Figure& a, const Figure& b) { return a.rays_per_s < b.rays_per_s; });
    return runs[runs.size() / 2];
}

#ifdef LUMEN_HAVE_EMBREE
struct EmbreeScene {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    EmbreeScene(const scene::Mesh& mesh, bool robust) {
        device = rtcNewDevice("threads=1");
        scene = rtcNewScene(device);
        if (robust) rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
        RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                              3 * sizeof(float), mesh.vertices.size()));
        for (size_t i = 0; i < mesh.vertices.size(); ++i)
            for (int k = 0; k < 3; ++k) v[3 * i + k] = float(mesh.vertices[i][k]);
        auto* ix = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                  3 * sizeof(unsigned), mesh.faces.size()));
        for (size_t i = 0; i < mesh.faces.size(); ++i)
            for (int k = 0; k < 3; ++k) ix[3 * i + k] = unsigned(mesh.faces[i].v[size_t(k)]);
        rtcCommitGeometry(geom);
        rtcAttachGeometry(scene, geom);
        rtcReleaseGeometry(geom);
        rtcCommitScene(scene);
    }
    ~EmbreeScene() {
        rtcReleaseScene(scene);
        rtcReleaseDevice(device);
    }
    bool intersect(const render::Ray& r, float tmax) const {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        RTCRayHit rh{};
        rh.ray.org_x = float(r.origin.x), rh.ray.org_y = float(r.origin.y), rh.ray.org_z = float(r.origin.z);
        rh.ray.dir_x = float(r.dir.x), rh.ray.dir_y = float(r.dir.y), rh.ray.dir_z = float(r.dir.z);
        rh.ray.tnear = 1e-4f, rh.ray.tfar = tmax, rh.ray.mask = ~0u;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene, &ctx, &rh);
        return rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    }
    bool occluded(const render::Ray& r, float tmax) const {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        RTCRay ray{};
        ray.org_x = float(r.origin.x), ray.org_y = float(r.origin.y), ray.org_z = float(r.origin.z);
        ray.dir_x = float(r.dir.x), ray.dir_y = float(r.dir.y), ray.dir_z = float(r.dir.z);
        ray.tnear = 1e-4f, ray.tfar = tmax, ray.mask = ~0u;
        rtcOccluded1(scene, &ctx, &ray);
        return ray.tfar < 0;  // Embree marks an occluded ray with tfar = -inf
    }
};
#endif

}  // namespace

int main(int argc, char** argv) {
    std::vector<long> sizes;
    for (int i = 1; i < argc; ++i) sizes.push_back(std::atol(argv[i]));
    if (sizes.empty()) sizes = {200000, 2000000};
    std::printf("%10s %-8s %9s %8s %8s %6s %8s %6s %10s %10s\n", "triangles", "rays", "count", "lumen",
                "Embree", "ratio", "robust", "ratio", "lumen hits", "Embree hits");
    for (long t : sizes) {
        auto object = std::make_shared<scene::Object>();
        object->shape = grid_mesh(t);
        const scene::Mesh& mesh = std::get<scene::Mesh>(object->shape);
        const long triangles = long(mesh.faces.size());
        auto build = Clock::now();
        const render::Geometry geometry(std::vector<scene::ObjectPtr>{object});
        const double lumen_build = seconds_since(build);
        const Rays rays = make_rays(geometry);
        render::Hit h;
        // Per kind of ray, the tracers in turn: lumen, Embree at its defaults, Embree robust.
        using Trace = std::function<int(size_t)>;
        std::vector<std::vector<Trace>> tracers(3);
        tracers[0] = {[&](size_t i) { return int(geometry.intersect(rays.primary[i], 1e-4, 1e30, h)); },
                      [&](size_t i) {
                          return int(geometry.occluded(rays.shadow[i], 1e-4, rays.shadow_length[i],
                                                       render::Query::Shadow));
                      },
                      [&](size_t i) { return int(geometry.intersect(rays.diffuse[i], 1e-4, 1e30, h)); }};
        double embree_build = 0;
#ifdef LUMEN_HAVE_EMBREE
        build = Clock::now();
        const EmbreeScene embree(mesh, false), robust(mesh, true);
        embree_build = seconds_since(build) / 2;
        for (int k = 1; k <= 2; ++k) {
            const EmbreeScene& e = k == 1 ? embree : robust;
            tracers[size_t(k)] = {
                [&e, &rays](size_t i) { return int(e.intersect(rays.primary[i], 1e30f)); },
                [&e, &rays](size_t i) { return int(e.occluded(rays.shadow[i], float(rays.shadow_length[i]))); },
                [&e, &rays](size_t i) { return int(e.intersect(rays.diffuse[i], 1e30f)); }};
        }
#endif
        const char* names[3] = {"primary", "shadow", "diffuse"};
        const size_t counts[3] = {rays.primary.size(), rays.shadow.size(), rays.diffuse.size()};
        for (int kind = 0; kind < 3; ++kind) {
            // The machine's speed drifts: the tracers take turns, and each figure is the median
            // of its rounds.
            std::vector<Figure> runs[3];
            for (int round = 0; round < kRounds; ++round)
                for (size_t k = 0; k < tracers.size(); ++k)
                    if (!tracers[k].empty()) runs[k].push_back(timed(counts[kind], tracers[k][size_t(kind)]));
            const Figure l = median(runs[0]), e = median(runs[1]), r = median(runs[2]);
            auto ratio = [&](const Figure& f) { return f.rays_per_s > 0 ? f.rays_per_s / l.rays_per_s : 0.0; };
            std::printf("%10ld %-8s %9zu %8.2f %8.2f %6.2f %8.2f %6.2f %10ld %10ld\n", triangles, names[kind],
                        counts[kind], l.rays_per_s / 1e6, e.rays_per_s / 1e6, ratio(e), r.rays_per_s / 1e6,
                        ratio(r), l.hits, e.hits);
        }
        std::printf("%10ld build s: lumen %.2f, Embree %.2f (one thread each)\n", triangles, lumen_build,
                    embree_build);
    }
    return 0;
}
