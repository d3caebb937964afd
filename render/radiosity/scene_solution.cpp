#include "render/radiosity/scene_solution.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <random>
#include <thread>

#include <glm/geometric.hpp>

#include "parser/diagnostics.hpp"
#include "render/camera.hpp"
#include "render/lights.hpp"
#include "render/radiosity/ray_cast.hpp"
#include "render/radiosity/solver.hpp"
#include "render/shadows.hpp"

namespace lumen::render::radiosity {

namespace {

constexpr double kMinDepth = 1e-4;  // as the tracer: nearer hits are ignored

double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Where the gathers and light samples of a vertex side start: a hair inside the adjacent
// elements (off shared edges and corners).
glm::dvec3 gather_origin(const SceneMesh& mesh, const MeshVertex& v) {
    return v.position + v.inward * (1e-3 * mesh.patch_size);
}

glm::dvec3 side_normal(const MeshVertex& v, size_t side) { return side ? -v.normal : v.normal; }

bool needs_light(const MeshVertex& v) {
    return v.rho.x > 0 || v.rho.y > 0 || v.rho.z > 0;
}

// Nearest hit that radiosity sees (no_radiosity objects are skipped).
bool radiosity_hit(const Intersector& geometry, const Ray& ray, Hit& hit) {
    double t_min = kMinDepth;
    for (int i = 0; i < 64; ++i) {
        if (!geometry.intersect(ray, t_min, std::numeric_limits<double>::infinity(), hit, false))
            return false;
        if (!hit.no_radiosity) return true;
        t_min = hit.t;
    }
    return false;
}

}  // namespace

void parallel_for(size_t n, int threads, const std::function<void(size_t, size_t)>& fn) {
    const size_t workers = std::max<size_t>(1, std::min<size_t>(size_t(std::max(threads, 1)), n));
    if (workers <= 1) {
        fn(0, n);
        return;
    }
    std::atomic<size_t> next{0};
    constexpr size_t chunk = 16;
    std::exception_ptr failure;
    std::mutex failure_mutex;
    auto work = [&] {
        try {
            for (size_t b = next.fetch_add(chunk); b < n; b = next.fetch_add(chunk))
                fn(b, std::min(n, b + chunk));
        } catch (...) {
            std::lock_guard lock(failure_mutex);
            if (!failure) failure = std::current_exception();
            next = n;
        }
    };
    std::vector<std::thread> pool;
    for (size_t i = 0; i < workers; ++i) pool.emplace_back(work);
    for (auto& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
}

glm::dvec3 VertexFormFactors::gather(size_t u, const std::vector<glm::dvec3>& B) const {
    glm::dvec3 g = env[u];
    for (uint32_t k = start[u]; k < start[u + 1]; ++k) g += double(weight[k]) * B[col[k]];
    return g;
}

glm::dvec3 background_radiance(const scene::Scene& scene, const glm::dvec3&) {
    const scene::Colour& bg = scene.background;
    return {bg.r, bg.g, bg.b};
}

int effective_bounces(const scene::Scene& scene, const RadiosityOptions& options) {
    if (options.bounces) return *options.bounces;
    const int rl = scene.globals.radiosity ? scene.globals.radiosity->recursion_limit : 2;
    return std::clamp(rl, 1, 20);
}

std::vector<glm::dvec3> direct_light(const scene::Scene& scene, const SceneMesh& mesh,
                                     const Intersector& geometry, int threads) {
    const std::vector<LightSource> lights = prepare_lights(scene.lights);
    std::vector<glm::dvec3> H(mesh.unknowns(), glm::dvec3(0));
    parallel_for(mesh.vertices.size(), threads, [&](size_t begin, size_t end) {
        TraceCounters counters;
        const InteriorList outside{};
        for (size_t v = begin; v < end; ++v) {
            const MeshVertex& mv = mesh.vertices[v];
            if (!needs_light(mv)) continue;
            const glm::dvec3 p = gather_origin(mesh, mv);
            for (const LightSource& l : lights) {
                LightSample ls;
                // POV's radiosity rays see area lights as point lights at their centre.
                if (!illuminate(l, p, ls)) continue;
                for (size_t side = 0; side < 2; ++side) {
                    const double c = glm::dot(side_normal(mv, side), ls.dir);
                    if (c <= 0) continue;
                    glm::dvec3 lc = ls.colour * c;
                    if (!l.shadowless)
                        lc *= shadow_filter(geometry, p, ls.dir, ls.distance, outside, counters);
                    H[2 * v + side] += lc;
                }
            }
        }
    });
    return H;
}

namespace {

// Casts `rays` stratified cosine-weighted rays from a vertex side (deterministic per side):
// on_hit(unknown, weight) for each vertex of the element a ray lands on (barycentric share
// of 1/rays), on_miss(direction) for rays that escape.
template <class OnHit, class OnMiss>
void cast_gather(const SceneMesh& mesh, const Intersector& geometry, size_t u, int rays,
                 OnHit&& on_hit, OnMiss&& on_miss) {
    const MeshVertex& mv = mesh.vertices[u / 2];
    const glm::dvec3 origin = gather_origin(mesh, mv);
    const glm::dvec3 n_side = side_normal(mv, u % 2);
    const int cells = std::max(1, int(std::lround(std::sqrt(double(rays)))));
    const double w = 1.0 / (cells * cells);
    std::mt19937_64 rng(0x9e3779b97f4a7c15ULL * (u + 1));
    std::uniform_real_distribution<double> U(0.0, 1.0);
    for (int i = 0; i < cells; ++i)
        for (int j = 0; j < cells; ++j) {
            const glm::dvec3 dir =
                cosine_direction(n_side, (i + U(rng)) / cells, (j + U(rng)) / cells);
            Hit hit;
            if (!radiosity_hit(geometry, Ray{origin, dir}, hit)) {
                on_miss(dir, w);
                continue;
            }
            glm::dvec3 bary;
            const long e = mesh.find(origin, dir, hit.t, 1e-4 + 1e-7 * hit.t, hit.object, bary);
            if (e < 0) continue;  // an object without elements: absorbs
            const MeshElement& el = mesh.elements[size_t(e)];
            const uint32_t hit_side = glm::dot(dir, el.normal) < 0 ? 0 : 1;
            for (int k = 0; k < 3; ++k)
                if (bary[k] > 0) on_hit(2 * el.v[k] + hit_side, w * bary[k]);
        }
}

}  // namespace

VertexFormFactors vertex_form_factors(const scene::Scene& scene, const SceneMesh& mesh,
                                      const Intersector& geometry, int rays, int threads) {
    const size_t n = mesh.unknowns();
    std::vector<std::vector<std::pair<uint32_t, float>>> rows(n);
    VertexFormFactors F;
    F.env.assign(n, glm::dvec3(0));
    parallel_for(mesh.vertices.size(), threads, [&](size_t begin, size_t end) {
        std::vector<std::pair<uint32_t, float>> entries;
        for (size_t v = begin; v < end; ++v) {
            if (!needs_light(mesh.vertices[v])) continue;  // ρ = 0: G is never used
            for (size_t u = 2 * v; u < 2 * v + 2; ++u) {
                entries.clear();
                cast_gather(
                    mesh, geometry, u, rays,
                    [&](uint32_t col, double w) { entries.emplace_back(col, float(w)); },
                    [&](const glm::dvec3& dir, double w) {
                        F.env[u] += w * background_radiance(scene, dir);
                    });
                std::sort(entries.begin(), entries.end());
                auto& row = rows[u];
                for (const auto& [c, x] : entries) {
                    if (!row.empty() && row.back().first == c) row.back().second += x;
                    else row.emplace_back(c, x);
                }
            }
        }
    });
    F.start.reserve(n + 1);
    F.start.push_back(0);
    for (const auto& row : rows) {
        for (const auto& [c, x] : row) {
            F.col.push_back(c);
            F.weight.push_back(x);
        }
        F.start.push_back(uint32_t(F.col.size()));
    }
    return F;
}

std::vector<char> visible_sides(const SceneMesh& mesh, const Intersector& geometry,
                                const CameraModel& camera, int width, int height) {
    std::vector<char> seen(mesh.unknowns(), 0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const Ray ray = camera.ray(x, y);
            Hit hit;
            if (!geometry.intersect(ray, kMinDepth, std::numeric_limits<double>::infinity(), hit,
                                    false))
                continue;
            glm::dvec3 bary;
            const long e = mesh.find(ray.origin, ray.dir, hit.t, 1e-4 + 1e-7 * hit.t, hit.object, bary);
            if (e < 0) continue;
            const MeshElement& el = mesh.elements[size_t(e)];
            const uint32_t side = glm::dot(ray.dir, el.normal) < 0 ? 0 : 1;
            for (uint32_t v : el.v) seen[2 * v + side] = 1;
        }
    return seen;
}

std::vector<glm::dvec3> final_gather(const scene::Scene& scene, const SceneMesh& mesh,
                                     const Intersector& geometry,
                                     const std::vector<glm::dvec3>& B,
                                     const std::vector<char>& wanted, int rays, int threads,
                                     const std::vector<glm::dvec3>& fallback) {
    std::vector<glm::dvec3> G = fallback;
    parallel_for(mesh.unknowns(), threads, [&](size_t begin, size_t end) {
        for (size_t u = begin; u < end; ++u) {
            if (!wanted[u] || !needs_light(mesh.vertices[u / 2])) continue;
            glm::dvec3 g(0);
            cast_gather(
                mesh, geometry, u, rays, [&](uint32_t col, double w) { g += w * B[col]; },
                [&](const glm::dvec3& dir, double w) { g += w * background_radiance(scene, dir); });
            G[u] = g;
        }
    });
    return smooth(mesh, G);
}

namespace {

// The dense system of the library solvers: B = (E + ρ(H + G_env)) + ρ F B.
RadiositySystem dense_system(const SceneMesh& mesh, const VertexFormFactors& F,
                             const std::vector<glm::dvec3>& H) {
    const size_t n = F.rows();
    constexpr size_t kMaxDense = 6000;
    if (n > kMaxDense)
        throw LumenError({}, "radiosity: " + std::to_string(n) +
                                 " unknowns are too many for a dense solver",
                         "use Radiosity_Method=jacobi or a larger Radiosity_Patch_Size");
    RadiositySystem s;
    s.F = FormFactorMatrix(n);
    s.rho.resize(n);
    s.emission.resize(n);
    s.area.resize(n);
    for (size_t u = 0; u < n; ++u) {
        const MeshVertex& v = mesh.vertices[u / 2];
        for (uint32_t k = F.start[u]; k < F.start[u + 1]; ++k) s.F(u, F.col[k]) += F.weight[k];
        s.rho[u] = v.rho;
        s.emission[u] = v.emission + v.rho * (H[u] + F.env[u]);
        s.area[u] = v.area > 0 ? v.area : 1e-12;
    }
    return s;
}

std::unique_ptr<Solver> make_solver(Method m) {
    switch (m) {
        case Method::Matrix: return make_lu_solver();
        case Method::GaussSeidel: return make_gauss_seidel_solver();
        case Method::Progressive: return make_progressive_solver();
        default: return make_jacobi_solver();
    }
}

void check_reflectance(const SceneMesh& mesh, std::vector<std::string>& warnings) {
    for (const MeshElement& e : mesh.elements) {
        const glm::dvec3 rho = mesh.vertices[e.v[0]].rho;
        if (std::max({rho.x, rho.y, rho.z}) >= 1) {
            warnings.push_back(e.object->loc.str() +
                               ": warning: radiosity: diffuse reflectance >= 1 (diffuse × "
                               "pigment); light never dies out, so only a bounce-limited "
                               "solve is meaningful");
            return;
        }
    }
}

}  // namespace

// One pass of neighbour averaging over the vertices sharing an element (same side): the
// indirect term is smooth away from contacts, and this cuts the per-vertex ray noise.
std::vector<glm::dvec3> smooth(const SceneMesh& mesh, const std::vector<glm::dvec3>& G) {
    std::vector<glm::dvec3> sum(G.size(), glm::dvec3(0));
    std::vector<double> weight(G.size(), 0.0);
    for (const MeshElement& e : mesh.elements)
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                for (uint32_t side = 0; side < 2; ++side) {
                    const double w = a == b ? 1.0 : 0.5;  // a vertex is in several elements
                    sum[2 * e.v[a] + side] += w * G[2 * e.v[b] + side];
                    weight[2 * e.v[a] + side] += w;
                }
    std::vector<glm::dvec3> out(G.size());
    for (size_t u = 0; u < G.size(); ++u) out[u] = weight[u] > 0 ? sum[u] / weight[u] : G[u];
    return out;
}

Solution solve_scene(const scene::Scene& scene, const SceneMesh& mesh,
                     const Intersector& geometry, const RadiosityOptions& options, int threads,
                     SolveInfo& info) {
    auto t0 = std::chrono::steady_clock::now();
    const std::vector<glm::dvec3> H = direct_light(scene, mesh, geometry, threads);
    const VertexFormFactors F = vertex_form_factors(scene, mesh, geometry, options.ff_rays, threads);
    info.form_factor_seconds = seconds_since(t0);
    t0 = std::chrono::steady_clock::now();
    check_reflectance(mesh, info.warnings);

    const size_t n = mesh.unknowns();
    Solution sol;
    sol.bounces = effective_bounces(scene, options);
    auto leaving = [&](size_t u, const glm::dvec3& G) {
        const MeshVertex& v = mesh.vertices[u / 2];
        return v.emission + v.rho * (H[u] + G);
    };
    auto gather_all = [&](const std::vector<glm::dvec3>& B) {
        std::vector<glm::dvec3> G(n);
        parallel_for(n, threads, [&](size_t b, size_t e) {
            for (size_t u = b; u < e; ++u) G[u] = F.gather(u, B);
        });
        return G;
    };
    Method method = options.method;
    if (method == Method::Auto)
        method = sol.bounces > 0 || n > 3000 ? Method::Jacobi : Method::Matrix;
    info.method = method_name(method);

    std::vector<glm::dvec3> B(n);
    for (size_t u = 0; u < n; ++u) B[u] = leaving(u, F.env[u]);  // B⁰
    if (method == Method::Jacobi) {
        if (sol.bounces > 0) info.iterations = 1;  // reported as bounces: the last is G
        // Sparse sweeps: one bounce each; bounce-limited (POV) or until the change is small.
        const int cap = sol.bounces > 0 ? sol.bounces - 1 : 10000;
        std::vector<glm::dvec3> G;
        for (int k = 0; k < cap; ++k) {
            G = gather_all(B);
            double change = 0, size = 1e-300;
            for (size_t u = 0; u < n; ++u) {
                const glm::dvec3 next = leaving(u, G[u]);
                const glm::dvec3 d = glm::abs(next - B[u]);
                change = std::max({change, d.x, d.y, d.z});
                size = std::max({size, next.x, next.y, next.z});
                B[u] = next;
            }
            ++info.iterations;
            if (sol.bounces == 0 && change <= options.tolerance * size) break;
            if (!std::isfinite(change)) {
                info.warnings.push_back("warning: radiosity: the iteration diverges (reflectance "
                                        ">= 1?); stopped after " + std::to_string(k + 1) +
                                        " sweeps");
                break;
            }
            if (k + 1 == cap && sol.bounces == 0)
                info.warnings.push_back("warning: radiosity: Jacobi stopped at its iteration cap");
        }
    } else {
        const RadiositySystem system = dense_system(mesh, F, H);
        const std::string problem = stability_problem(system);
        if (!problem.empty()) info.warnings.push_back("warning: radiosity: " + problem);
        auto solver = make_solver(method);
        SolveOptions so;
        so.tolerance = options.tolerance;
        so.max_iterations = method == Method::Progressive ? int(100 * n) : 100000;
        so.allow_unstable = true;
        const SolveReport report = solve(*solver, system, so);
        info.iterations = report.iterations;
        if (report.status != SolveStatus::Converged)
            info.warnings.push_back("warning: radiosity: " + solver->name() + ": " + report.message);
        B = solver->display();
        sol.bounces = 0;
    }
    for (glm::dvec3& b : B)
        if (!std::isfinite(b.x + b.y + b.z)) b = glm::dvec3(0);  // never a NaN in a pixel
    sol.G = gather_all(B);
    sol.B = std::move(B);
    info.solve_seconds = seconds_since(t0);
    return sol;
}

}  // namespace lumen::render::radiosity
