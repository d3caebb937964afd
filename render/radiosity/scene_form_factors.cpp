// Vertex form factors of a scene mesh by the three methods of Radiosity_Form_Factors:
// ray casting (the default), Lambert's analytic point-to-polygon
// value with sampled visibility for emitters and near pairs (where a few rays are noisiest),
// and the hemicube as the lecture's baseline, all cast through the renderer's geometry.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "render/radiosity/form_factor.hpp"
#include "render/radiosity/patch.hpp"
#include "render/radiosity/sample_rng.hpp"
#include "render/radiosity/scene_solution.hpp"
#include "render/radiosity/vertex_rays.hpp"

namespace lumen::render::radiosity {

namespace {

using Row = std::vector<std::pair<uint32_t, float>>;

// The hemicube's pixel directions in the local frame (x, y tangent, z normal) and their
// delta form factors (Cohen & Greenberg 1985; hemicube.cpp's library version).
struct HemicubeDirections {
    std::vector<glm::dvec3> dir;
    std::vector<double> weight;
    explicit HemicubeDirections(int resolution) {
        const int res = std::max(2, resolution - resolution % 2);
        const double pixel = 2.0 / res, dA = pixel * pixel, pi = std::numbers::pi;
        for (int i = 0; i < res; ++i)
            for (int j = 0; j < res; ++j) {
                const double u = -1 + (i + 0.5) * pixel, v = -1 + (j + 0.5) * pixel;
                const double q = u * u + v * v + 1;
                add({u, v, 1}, dA / (pi * q * q));
            }
        for (int side = 0; side < 4; ++side)
            for (int i = 0; i < res; ++i)
                for (int k = 0; k < res / 2; ++k) {
                    const double u = -1 + (i + 0.5) * pixel, z = (k + 0.5) * pixel;
                    const double q = u * u + z * z + 1, sign = side % 2 ? -1.0 : 1.0;
                    add(side < 2 ? glm::dvec3(sign, u, z) : glm::dvec3(u, sign, z),
                        dA * z / (pi * q * q));
                }
    }
    void add(const glm::dvec3& d, double w) {
        dir.push_back(glm::normalize(d));
        weight.push_back(w);
    }
};

// Lambert's value from a vertex side to each element near it (or emitting), times the
// visible fraction of a few points on the element; the elements so counted, sorted.
class AnalyticPairs {
public:
    AnalyticPairs(const SceneMesh& mesh, const Intersector& geometry)
        : mesh_(mesh), geometry_(geometry), reach_(2 * mesh.patch_size) {
        for (uint32_t e = 0; e < mesh.elements.size(); ++e) {
            const auto& v = mesh.elements[e].v;
            for (uint32_t k : v)
                if (glm::length(mesh.vertices[k].emission) > 0) {
                    emitters_.push_back(e);
                    break;
                }
        }
    }

    void add(const glm::dvec3& origin, const glm::dvec3& normal, uint64_t seed, Row& row,
             std::vector<uint32_t>& counted) const {
        counted = emitters_;
        near(origin, counted);
        std::sort(counted.begin(), counted.end());
        counted.erase(std::unique(counted.begin(), counted.end()), counted.end());
        SampleRng rng(seed);
        for (uint32_t e : counted) {
            const MeshElement& el = mesh_.elements[e];
            const Patch tri = make_patch({mesh_.vertices[el.v[0]].position,
                                          mesh_.vertices[el.v[1]].position,
                                          mesh_.vertices[el.v[2]].position});
            const double f = point_to_polygon(origin, normal, tri);
            if (!(f > 0)) continue;
            int seen = 0;
            constexpr int kSamples = 4;  // stratified 2 x 2 over the element
            for (int k = 0; k < kSamples; ++k) {
                const glm::dvec3 p =
                    sample_point(tri, ((k & 1) + rng.uniform()) / 2, ((k >> 1) + rng.uniform()) / 2);
                const glm::dvec3 d = p - origin;
                const double dist = glm::length(d);
                Hit hit;
                if (!radiosity_hit(geometry_, Ray{origin, d / dist}, hit) ||
                    hit.t > dist * (1 - 1e-6) - 1e-4 * mesh_.patch_size)
                    ++seen;
            }
            if (!seen) continue;
            const uint32_t side = glm::dot(origin - tri.centroid, el.normal) > 0 ? 0 : 1;
            for (uint32_t v : el.v)
                row.emplace_back(2 * v + side, float(f * seen / (3.0 * kSamples)));
        }
    }

private:
    // Elements whose grid cells lie within reach of p (a superset of those within reach).
    void near(const glm::dvec3& p, std::vector<uint32_t>& out) const {
        if (mesh_.cell_start.empty()) return;
        auto cell = [&](const glm::dvec3& q) {
            return glm::clamp(glm::ivec3(glm::floor((q - mesh_.grid_origin) / mesh_.grid_cell)),
                              glm::ivec3(0), mesh_.grid_size - 1);
        };
        const glm::ivec3 lo = cell(p - glm::dvec3(reach_)), hi = cell(p + glm::dvec3(reach_));
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x) {
                    const size_t c =
                        (size_t(z) * mesh_.grid_size.y + y) * mesh_.grid_size.x + x;
                    out.insert(out.end(), mesh_.cell_items.begin() + mesh_.cell_start[c],
                               mesh_.cell_items.begin() + mesh_.cell_start[c + 1]);
                }
    }

    const SceneMesh& mesh_;
    const Intersector& geometry_;
    double reach_;
    std::vector<uint32_t> emitters_;
};

}  // namespace

VertexFormFactors vertex_form_factors(const scene::Scene& scene, const SceneMesh& mesh,
                                      const Intersector& geometry,
                                      const RadiosityOptions& options, int threads,
                                      const SurfaceRadiance* unmeshed) {
    const size_t n = mesh.unknowns();
    std::vector<Row> rows(n);
    VertexFormFactors F;
    F.env.assign(n, glm::dvec3(0));
    const FormFactorMethod method = options.form_factors;
    const int ff_rays = effective_ff_rays(scene, options);
    const HemicubeDirections cube(method == FormFactorMethod::Hemicube ? options.hemicube_res : 2);
    const AnalyticPairs analytic(mesh, geometry);
    parallel_for(mesh.vertices.size(), threads, [&](size_t begin, size_t end) {
        Row entries;
        std::vector<uint32_t> counted;  // elements the analytic pass covered
        for (size_t v = begin; v < end; ++v) {
            const MeshVertex& mv = mesh.vertices[v];
            if (!needs_light(mv)) continue;  // ρ = 0: G is never used
            const glm::dvec3 origin = gather_origin(mesh, mv);
            for (size_t u = 2 * v; u < 2 * v + 2; ++u) {
                if (mv.sealed >> (u % 2) & 1) continue;  // nothing sees this side
                entries.clear();
                const glm::dvec3 normal = side_normal(mv, u % 2);
                auto on_hit = [&](long e, uint32_t col, double w, double) {
                    if (!std::binary_search(counted.begin(), counted.end(), uint32_t(e)))
                        entries.emplace_back(col, float(w));
                };
                auto on_miss = [&](const glm::dvec3& dir, double w) {
                    F.env[u] += w * background_radiance(scene, dir);
                };
                auto on_unmeshed = [&](const Hit& hit, const glm::dvec3& dir, double w, long,
                                       const glm::dvec3&) {
                    if (unmeshed) F.env[u] += w * unmeshed->leaving(hit, dir, 1, -1, {});
                };
                counted.clear();
                if (method == FormFactorMethod::Hemicube) {
                    // A random turn about the normal per vertex side breaks the aliasing.
                    glm::dvec3 t, b;
                    tangent_frame(normal, t, b);
                    const double turn =
                        2 * std::numbers::pi * SampleRng(side_seed(u)).uniform();
                    const glm::dvec3 x = std::cos(turn) * t + std::sin(turn) * b,
                                     y = glm::cross(normal, x);
                    for (size_t k = 0; k < cube.dir.size(); ++k) {
                        const glm::dvec3& d = cube.dir[k];
                        trace_ray(mesh, geometry, origin, d.x * x + d.y * y + d.z * normal,
                                  cube.weight[k], on_hit, on_miss, on_unmeshed);
                    }
                } else {
                    if (method == FormFactorMethod::Analytic)
                        analytic.add(origin, normal, side_seed(u) ^ 0x5bd1e995, entries, counted);
                    cast_rays(mesh, geometry, origin, normal, side_seed(u), ff_rays,
                              on_hit, on_miss, on_unmeshed);
                }
                std::sort(entries.begin(), entries.end());
                Row& row = rows[u];
                for (const auto& [c, x] : entries) {
                    if (!row.empty() && row.back().first == c) row.back().second += x;
                    else row.emplace_back(c, x);
                }
            }
        }
    });
    F.start.reserve(n + 1);
    F.start.push_back(0);
    for (const Row& row : rows) {
        for (const auto& [c, x] : row) {
            F.col.push_back(c);
            F.weight.push_back(x);
        }
        F.start.push_back(uint32_t(F.col.size()));
    }
    return F;
}

}  // namespace lumen::render::radiosity
