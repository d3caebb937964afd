#include "render/radiosity/point_gather.hpp"

#include <algorithm>
#include <bit>
#include <chrono>
#include <functional>

#include <glm/geometric.hpp>

#include "render/radiosity/surface_light.hpp"

namespace lumen::render::radiosity {

PointGather::PointGather(const RenderFrame& frame, const SceneMesh& mesh,
                         const std::vector<glm::dvec3>* B, const PointGatherSettings& settings,
                         const std::vector<glm::dvec3>* indirect)
    : frame_(frame), mesh_(mesh), B_(B), s_(settings), indirect_(B ? indirect : nullptr) {
    if (!B_) return;
    caches_ = make_caches();
    if (indirect_)
        for (const glm::dvec3& g : *indirect_) any_indirect_ = any_indirect_ || g != glm::dvec3(0);
}

PointGather::Caches PointGather::make_caches() const {
    Caches caches;
    CacheSettings c = s_.cache;
    for (int level = 1; level <= std::max(1, s_.bounces); ++level) {
        caches.push_back(std::make_unique<IrradianceCache>(c, mesh_.bounds.hi));
        c.error *= 2;  // deeper levels are seen through a gather: coarser is enough
    }
    return caches;
}

namespace {
// splitmix64's finaliser.
uint64_t mix64(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

// The caches of the render block whose gather runs on this thread, for its deeper levels.
thread_local const std::vector<std::unique_ptr<IrradianceCache>>* t_block_caches = nullptr;
}  // namespace

glm::dvec3 PointGather::incident(const glm::dvec3& p, const glm::dvec3& n, ThreadState& state) const {
    if (state.block_scratch_owner != this || state.block_scratch_block != state.block ||
        !state.block_scratch) {
        state.block_scratch = std::make_shared<Caches>(make_caches());
        state.block_scratch_owner = this;
        state.block_scratch_block = state.block;
    }
    const Caches& caches = *static_cast<const Caches*>(state.block_scratch.get());
    const Caches* outer = t_block_caches;
    t_block_caches = &caches;
    const size_t before = caches.front()->size();
    const glm::dvec3 g = incident_in(caches, p, n, 1);
    // Counted only when a gather added a record: most calls are lookups, on every thread.
    if (const size_t added = caches.front()->size() - before) block_records_ += added;
    t_block_caches = outer;
    return g;
}

void PointGather::with_worker_caches(size_t worker, const std::function<void()>& work) const {
    if (!B_) {
        work();
        return;
    }
    const Caches* caches = nullptr;
    {
        std::lock_guard lock(workers_mutex_);
        if (worker_caches_.size() <= worker) worker_caches_.resize(worker + 1);
        if (!worker_caches_[worker]) worker_caches_[worker] = std::make_unique<Caches>(make_caches());
        caches = worker_caches_[worker].get();
    }
    const Caches* outer = t_block_caches;
    t_block_caches = caches;
    try {
        work();
    } catch (...) {
        t_block_caches = outer;
        throw;
    }
    t_block_caches = outer;
}

glm::dvec3 PointGather::incident(const glm::dvec3& p, const glm::dvec3& n, int level) const {
    return incident_in(t_block_caches ? *t_block_caches : caches_, p, n, level);
}

glm::dvec3 PointGather::leaving(const Hit& hit, const glm::dvec3& dir, int level, long element,
                                const glm::dvec3& bary) const {
    // On an element, its corners' material: the same result where it matters (the direct
    // light is what an element blurs) without evaluating the texture at every hit
    // (gamma/gamma_showcase.pov's gathers spent an eighth of their time in its noise).
    SurfaceMaterial m;
    if (element >= 0) {
        const MeshElement& el = mesh_.elements[size_t(element)];
        for (int k = 0; k < 3; ++k) {
            m.rho += bary[k] * mesh_.vertices[el.v[k]].rho;
            m.emission += bary[k] * mesh_.vertices[el.v[k]].emission;
        }
        m.brilliance = mesh_.vertices[el.v[0]].brilliance;
    } else {
        m = surface_material(hit.texture, hit.point, s_.ambient_emission);
    }
    if (m.rho == glm::dvec3(0)) return m.emission;
    glm::dvec3 n = hit.normal;
    if (glm::dot(n, dir) > 0) n = -n;  // the side the ray arrives on
    // Lifted as the tracer lifts its shadow rays off a surface.
    const glm::dvec3 p = hit.point + n * (1e-6 * std::max(1.0, mesh_.patch_size));
    TraceCounters counters;
    glm::dvec3 in;
    // Up to kAllLights lights, a shadow ray to each, as POV-Ray's radiosity rays trace them;
    // more (radiosity/cornell.pov's 16, an area light built of point lights), one picked by
    // a number the hit itself gives (deterministic): the gather's many hits average the pick.
    constexpr size_t kAllLights = 4;
    if (frame_.lights().size() > kAllLights) {
        uint64_t h = 0x9e3779b97f4a7c15ULL;
        for (double x : {hit.point.x, hit.point.y, hit.point.z, dir.x, dir.y})
            h = mix64(h ^ std::bit_cast<uint64_t>(x));
        const double u = double(h >> 11) * 0x1.0p-53;
        in = direct_light_one_of(frame_.lights(), frame_.geometry(), p, n, m.brilliance, u,
                                 counters);
    } else {
        in = direct_light_at(frame_.lights(), frame_.geometry(), p, n, m.brilliance, counters);
    }
    if (element >= 0 && indirect_) {  // the solution's indirect light, over the element
        const uint32_t side = seen_side(mesh_.elements[size_t(element)], hit.normal, -dir);
        in += interpolate_sides(mesh_, *indirect_, element, bary, side);
    } else if (B_ && level < s_.bounces) {
        in += incident(hit.point, n, level + 1);
    }
    return m.emission + m.rho * in;
}

glm::dvec3 PointGather::incident_in(const Caches& caches, const glm::dvec3& p,
                                    const glm::dvec3& n, int level) const {
    IrradianceCache& cache = *caches[size_t(std::clamp(level, 1, int(caches.size())) - 1)];
    glm::dvec3 g;
    if (cache.lookup(p, n, g)) return g;
    const auto t0 = std::chrono::steady_clock::now();
    // Deterministic per point, whichever thread gets here first.
    uint64_t seed = 0x9e3779b97f4a7c15ULL + uint64_t(level);
    for (double x : {p.x, p.y, p.z, n.x, n.y, n.z})
        seed = seed * 1099511628211ULL ^ std::hash<double>{}(x);
    const int rays = level == 1 ? s_.rays : std::max(16, s_.rays / 4);
    const GatherResult r =
        gather_point(frame_.scene(), mesh_, frame_.geometry(), *B_,
                     p + n * (1e-5 * mesh_.patch_size), n, rays, seed, this, level,
                     s_.gradients);
    cache.insert(p, n, r.G, r.harmonic_distance, r.gradients);
    if (level == 1)
        gather_ns_ += uint64_t(std::chrono::duration<double, std::nano>(
                                   std::chrono::steady_clock::now() - t0)
                                   .count());
    // The cache's faded average where the new record now covers p.
    if (!cache.lookup(p, n, g)) g = r.G;
    return g;
}

size_t PointGather::cache_points() const {
    size_t n = block_records_;
    for (const auto& c : caches_) n += c->size();
    std::lock_guard lock(workers_mutex_);
    for (const auto& w : worker_caches_)
        if (w)
            for (const auto& c : *w) n += c->size();
    return n;
}

}  // namespace lumen::render::radiosity
