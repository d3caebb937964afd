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

#include "base/diagnostics.hpp"
#include "base/stop_request.hpp"
#include "render/camera.hpp"
#include "render/lights.hpp"
#include "render/radiosity/point_gather.hpp"
#include "render/radiosity/ray_cast.hpp"
#include "render/radiosity/solver.hpp"
#include "render/radiosity/sparse_solve.hpp"
#include "render/radiosity/surface_light.hpp"
#include "render/radiosity/vertex_rays.hpp"
#include "render/shadows.hpp"
#include "render/sky.hpp"

namespace lumen::render::radiosity {

namespace {


double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}


// Runs `work(worker)` on `workers` threads; the first exception stops the others' next chunk
// (they poll `stop`) and is rethrown.
void run_workers(size_t workers, const std::function<void(size_t, std::atomic<bool>&)>& work) {
    std::exception_ptr failure;
    std::mutex failure_mutex;
    std::atomic<bool> stop{false};
    std::vector<std::thread> pool;
    for (size_t w = 0; w < workers; ++w)
        pool.emplace_back([&, w] {
            try {
                work(w, stop);
            } catch (...) {
                std::lock_guard lock(failure_mutex);
                if (!failure) failure = std::current_exception();
                stop = true;
            }
        });
    for (auto& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
}

}  // namespace

void parallel_for(size_t n, int threads, const std::function<void(size_t, size_t)>& fn) {
    const size_t workers = std::max<size_t>(1, std::min<size_t>(size_t(std::max(threads, 1)), n));
    throw_if_stop_requested();  // SIGINT/SIGTERM: also polled before each chunk below
    if (workers <= 1) {
        fn(0, n);
        return;
    }
    std::atomic<size_t> next{0};
    // Chunks of up to 16 items, small enough that each worker takes several: one costly last
    // chunk of a short list (a subdivision level's few new vertices) would keep the others idle.
    const size_t chunk = std::clamp<size_t>(n / (8 * workers), 1, 16);
    run_workers(workers, [&](size_t, std::atomic<bool>& stop) {
        for (size_t b = next.fetch_add(chunk); b < n && !stop; b = next.fetch_add(chunk)) {
            throw_if_stop_requested();
            fn(b, std::min(n, b + chunk));
        }
    });
}

void parallel_for_dealt(size_t n, int threads,
                        const std::function<void(size_t, size_t, size_t)>& fn) {
    const size_t workers = std::max<size_t>(1, size_t(std::max(threads, 1)));
    throw_if_stop_requested();
    if (workers <= 1 || n <= 1) {
        if (n > 0) fn(0, 0, n);
        return;
    }
    const size_t chunk = std::clamp<size_t>(n / (8 * workers), 1, 16);
    run_workers(workers, [&](size_t w, std::atomic<bool>& stop) {
        for (size_t b = w * chunk; b < n && !stop; b += workers * chunk) {
            throw_if_stop_requested();
            fn(w, b, std::min(n, b + chunk));
        }
    });
}

glm::dvec3 VertexFormFactors::gather(size_t u, const std::vector<glm::dvec3>& B) const {
    glm::dvec3 g = env[u];
    for (uint32_t k = start[u]; k < start[u + 1]; ++k) g += double(weight[k]) * B[col[k]];
    return g;
}

glm::dvec3 background_radiance(const scene::Scene& scene, const glm::dvec3& dir) {
    return sky_colour(scene, dir);
}

int effective_bounces(const scene::Scene& scene, const RadiosityOptions& options) {
    if (options.bounces) return *options.bounces;
    const int rl = scene.globals.radiosity ? scene.globals.radiosity->recursion_limit : 2;
    return std::clamp(rl, 1, 20);
}

int effective_ff_rays(const scene::Scene& scene, const RadiosityOptions& options) {
    if (options.ff_rays > 0) return options.ff_rays;
    const bool one_bounce = effective_bounces(scene, options) == 1 &&
                            (options.method == Method::Auto || options.method == Method::Jacobi);
    return one_bounce ? 4 : 16;
}

bool needs_form_factors(const scene::Scene& scene, const RadiosityOptions& options) {
    const bool one_bounce = effective_bounces(scene, options) == 1 &&
                            (options.method == Method::Auto || options.method == Method::Jacobi);
    return !one_bounce || options.ff_rays > 0 || options.form_factors != FormFactorMethod::RayCast;
}

namespace {

// A copy of the same declaration: scenes place copies on top of each other
// (radiosity/patio-radio_36.pov's four balconies of each side, one per rotated copy of its
// Group1), and the tracer answers with whichever copy comes first.
bool same_declaration(const scene::Object* a, const scene::Object* b) {
    return a && b && a->loc.file == b->loc.file && a->loc.line == b->loc.line &&
           a->loc.column == b->loc.column && a->loc.line != 0;
}

}  // namespace

bool onto_surface(const Intersector& geometry, const scene::Object* object, glm::dvec3& p,
                  glm::dvec3& n, double reach) {
    const Ray probe{p + n * reach, -n};
    // The object's hit nearest p, not the first: with a reach wider than the object (a
    // mesh's narrow neck, a thin shell) the probe starts beyond its far side.
    double t_min = 0, best = INFINITY;
    Hit nearest;
    for (int i = 0; i < 8; ++i) {
        Hit hit;
        if (!geometry.intersect(probe, t_min, 2 * reach, hit, Query::All)) break;
        if (hit.t - reach >= best) break;  // the rest lie farther from p
        const double c = glm::dot(hit.normal, n);
        // A copy must face the same way: a neighbour made by the same loop or macro that
        // touches the object face to face faces the other way.
        const bool own = hit.object == object || (same_declaration(hit.object, object) && c > 0.5);
        if (own && std::fabs(c) > 0.5 && std::isfinite(c) && std::fabs(hit.t - reach) < best) {
            best = std::fabs(hit.t - reach);
            nearest = hit;
        }
        t_min = hit.t;
    }
    if (best == INFINITY) return false;
    const double c = glm::dot(nearest.normal, n);
    p = nearest.point;
    n = c > 0 ? nearest.normal : -nearest.normal;
    return true;
}

std::vector<glm::dvec3> direct_light(const RenderFrame& frame, const SceneMesh& mesh, int threads) {
    // Sampled at the elements' centroids, on the true surface, and given to each vertex side
    // as the area-weighted mean of its elements': a vertex sits on an object's edge or where
    // it meets another, where occluders are, and its own sample made B low all around it
    // (radiosity/patio-radio_37.pov came out 0.010 darker than POV-Ray on average).
    const size_t ne = mesh.elements.size();
    std::vector<glm::dvec3> He(2 * ne, glm::dvec3(0));
    parallel_for(ne, threads, [&](size_t begin, size_t end) {
        TraceCounters counters;
        for (size_t i = begin; i < end; ++i) {
            const MeshElement& e = mesh.elements[i];
            const MeshVertex& a = mesh.vertices[e.v[0]];
            const MeshVertex& b = mesh.vertices[e.v[1]];
            const MeshVertex& c = mesh.vertices[e.v[2]];
            if (!needs_light(a) && !needs_light(b) && !needs_light(c)) continue;
            glm::dvec3 p = (a.position + b.position + c.position) / 3.0, n = e.normal;
            const double size = std::max({glm::length(b.position - a.position),
                                          glm::length(c.position - b.position),
                                          glm::length(a.position - c.position)});
            // A chord of a curved shape lies inside it: from there every light is shadowed.
            onto_surface(frame.geometry(), e.object, p, n, 0.25 * size + 1e-6 * mesh.patch_size);
            He[2 * i] = direct_light_at(frame.lights(), frame.geometry(), p, n, a.brilliance,
                                        counters, &He[2 * i + 1]);
        }
    });
    std::vector<glm::dvec3> H(mesh.unknowns(), glm::dvec3(0));
    std::vector<double> weight(mesh.vertices.size(), 0.0);
    for (size_t i = 0; i < ne; ++i) {
        const MeshElement& e = mesh.elements[i];
        for (uint32_t v : e.v) {
            // Sides are the vertex's: its normal may face the element's back (welded shells).
            const size_t same = glm::dot(e.normal, mesh.vertices[v].normal) >= 0 ? 0 : 1;
            H[2 * v] += e.area * He[2 * i + same];
            H[2 * v + 1] += e.area * He[2 * i + (1 - same)];
            weight[v] += e.area;
        }
    }
    parallel_for(mesh.vertices.size(), threads, [&](size_t begin, size_t end) {
        TraceCounters counters;
        for (size_t v = begin; v < end; ++v) {
            const MeshVertex& mv = mesh.vertices[v];
            if (!needs_light(mv)) {
                H[2 * v] = H[2 * v + 1] = glm::dvec3(0);
            } else if (weight[v] > 0) {
                H[2 * v] /= weight[v];
                H[2 * v + 1] /= weight[v];
            } else {  // no element with an area: its own sample
                H[2 * v] = direct_light_at(frame.lights(), frame.geometry(),
                                           gather_origin(mesh, mv), mv.normal, mv.brilliance,
                                           counters, &H[2 * v + 1]);
            }
        }
    });
    return H;
}

std::vector<char> visible_sides(const SceneMesh& mesh, const Intersector& geometry,
                                const CameraModel& camera, int width, int height, int threads) {
    // Rows in parallel; threads may mark the same side, so the marks are atomic stores.
    std::vector<char> seen(mesh.unknowns(), 0);
    parallel_for(size_t(std::max(height, 0)), threads, [&](size_t begin, size_t end) {
        for (size_t y = begin; y < end; ++y)
            for (int x = 0; x < width; ++x) {
                const std::optional<Ray> sample = camera.ray(x, double(y));
                if (!sample) continue;
                const Ray& ray = *sample;
                Hit hit;
                if (!geometry.intersect(ray, kMinDepth, std::numeric_limits<double>::infinity(),
                                        hit, Query::All))
                    continue;
                glm::dvec3 bary;
                const long e = mesh.find(ray.origin, ray.dir, hit.t, 1e-4 + 1e-7 * hit.t,
                                         hit.object, bary);
                if (e < 0) continue;
                const MeshElement& el = mesh.elements[size_t(e)];
                const uint32_t side = seen_side(el, hit.normal, -ray.dir);
                for (uint32_t v : el.v)
                    std::atomic_ref<char>(seen[2 * v + side]).store(1, std::memory_order_relaxed);
            }
    });
    return seen;
}

GatherResult gather_point(const scene::Scene& scene, const SceneMesh& mesh,
                          const Intersector& geometry, const std::vector<glm::dvec3>& B,
                          const glm::dvec3& origin, const glm::dvec3& normal, int rays,
                          uint64_t seed, const SurfaceRadiance* unmeshed, int level,
                          bool gradients) {
    GatherResult r;
    double inv_dist = 0, weight = 0;
    // Each stratum's radiance and distance, for the gradients.
    GatherStrata strata;
    size_t at = 0;
    auto record = [&](const glm::dvec3& weighted, double t) {  // weighted: w x radiance
        if (!gradients) return;
        strata.L[at] += weighted * double(strata.m * strata.n);  // each ray weighs 1/(m n)
        strata.R[at] = t;
    };
    cast_rays(
        mesh, geometry, origin, normal, seed, rays,
        [&](long, uint32_t col, double w, double t) {
            r.G += w * B[col];
            inv_dist += w / std::max(t, 1e-9);
            weight += w;
            record(w * B[col], t);
        },
        [&](const glm::dvec3& dir, double w) {
            const glm::dvec3 in = w * background_radiance(scene, dir);
            r.G += in;
            record(in, INFINITY);
        },
        [&](const Hit& hit, const glm::dvec3& dir, double w, long e, const glm::dvec3& bary) {
            const glm::dvec3 in = unmeshed ? w * unmeshed->leaving(hit, dir, level, e, bary)
                                           : glm::dvec3(0);
            r.G += in;
            record(in, hit.t);
            inv_dist += w / std::max(hit.t, 1e-9);
            weight += w;
        },
        [&](int i, int j, int cells) {
            if (!gradients) return;
            if (strata.L.empty()) {
                strata.m = strata.n = cells;
                strata.L.assign(size_t(cells) * cells, glm::dvec3(0));
                strata.R.assign(size_t(cells) * cells, INFINITY);
            }
            at = size_t(i * cells + j);
        },
        [&](const glm::dvec3&, double w) {
            // Started inside solid matter (a vertex under a box standing on its surface, a
            // torus ring sunk into a column): what it meets there is no light that reaches
            // the surface outside. Left out; the rest stands for the hemisphere.
            r.inside += w;
            return true;
        },
        HitEvaluation{unmeshed && unmeshed->evaluates_every_hit(),
                      !unmeshed || unmeshed->uses_element(level)});
    if (r.inside > 0 && r.inside < 1) r.G /= 1 - r.inside;
    r.harmonic_distance = inv_dist > 0 ? weight / inv_dist : INFINITY;
    if (gradients) {
        glm::dvec3 t, b;
        tangent_frame(normal, t, b);
        r.gradients = irradiance_gradients(strata, t, b);
    }
    return r;
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
                         "use Radiosity_Method=gauss_seidel, progressive or jacobi (sparse), or a "
                         "larger Radiosity_Patch_Size");
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

Solution solve_scene(const RenderFrame& frame, const SceneMesh& mesh,
                     const RadiosityOptions& options, int threads,
                     SolveInfo& info) {
    auto t0 = std::chrono::steady_clock::now();
    const scene::Scene& scene = frame.scene();
    const Intersector& geometry = frame.geometry();
    const std::vector<glm::dvec3> H = direct_light(frame, mesh, threads);
    // Surfaces without elements reflect the direct light into the solve (their own indirect
    // light needs the solution: the display's point gathers add it).
    PointGatherSettings direct_only;
    direct_only.ambient_emission = ambient_emission(scene);
    const PointGather unmeshed(frame, mesh, nullptr, direct_only);
    const bool form_factors = needs_form_factors(scene, options);
    VertexFormFactors F;
    if (form_factors) F = vertex_form_factors(scene, mesh, geometry, options, threads, &unmeshed);
    info.form_factor_seconds = seconds_since(t0);
    info.ff_rays = form_factors ? effective_ff_rays(scene, options) : 0;
    t0 = std::chrono::steady_clock::now();

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
    // Light that never dies out matters only to a solve run to convergence: POV's
    // recursion_limit (Jacobi's bounces) stops it anyway (the stacker scenes' white*1.4 boxes).
    if (!(method == Method::Jacobi && sol.bounces > 0)) check_reflectance(mesh, info.warnings);

    std::vector<glm::dvec3> B(n);
    // B⁰: what leaves before any bounce. Bounce-limited, it is E + ρH alone, as POV's
    // deepest radiosity rays see a surface: the sky's light (env) arrives with the first
    // gather, like every other surface's, so recursion_limit 1 gets one bounce of it, not two.
    const bool limited = method == Method::Jacobi && sol.bounces > 0;
    for (size_t u = 0; u < n; ++u) B[u] = leaving(u, limited ? glm::dvec3(0) : F.env[u]);
    if (method == Method::Jacobi) {
        if (sol.bounces > 0) info.iterations = 1;  // reported as bounces: the last is G
        // Sparse sweeps: one bounce each; bounce-limited (POV) or until the change is small.
        const int cap = sol.bounces > 0 ? sol.bounces - 1 : 10000;
        std::vector<glm::dvec3> G = limited ? std::vector<glm::dvec3>(n) : F.env;
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
        sol.indirect = std::move(G);
    } else if (method == Method::GaussSeidel || method == Method::Progressive) {
        // On the sparse rows: no dense matrix, no cap on the unknowns.
        std::vector<glm::dvec3> rho(n), c(n);
        std::vector<double> area(n);
        for (size_t u = 0; u < n; ++u) {
            const MeshVertex& v = mesh.vertices[u / 2];
            rho[u] = v.rho;
            c[u] = B[u];
            area[u] = v.area > 0 ? v.area : 1e-12;
        }
        const SparseSolve r =
            method == Method::GaussSeidel
                ? sparse_gauss_seidel(F, rho, c, options.tolerance, 100000)
                : sparse_progressive(F, rho, c, area, options.tolerance, long(1000) * long(n));
        info.iterations = int(std::min<long>(r.iterations, INT32_MAX));
        if (!r.converged)
            info.warnings.push_back(std::string("warning: radiosity: ") + method_name(method) +
                                    " stopped before its tolerance (" +
                                    std::to_string(r.iterations) + " steps)");
        B = r.B;
        sol.bounces = 0;
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
    for (glm::dvec3& g : sol.indirect)
        if (!std::isfinite(g.x + g.y + g.z)) g = glm::dvec3(0);
    if (form_factors) sol.G = gather_all(B);
    // The converged solvers' B is E + ρ(H + F B): its indirect light is the next gather's.
    if (sol.indirect.size() != n) sol.indirect = form_factors ? sol.G : std::vector<glm::dvec3>(n);
    sol.B = std::move(B);
    info.solve_seconds = seconds_since(t0);
    return sol;
}

}  // namespace lumen::render::radiosity
