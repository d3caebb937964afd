// The rays of a vertex gather (internal to render/radiosity): where a ray from a vertex side
// lands on the scene mesh, for the form factors, the final gather and the gather display.
#pragma once
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "render/intersector.hpp"
#include "render/radiosity/ray_cast.hpp"
#include "render/radiosity/sample_rng.hpp"
#include "render/radiosity/scene_mesh.hpp"

namespace lumen::render::radiosity {

inline constexpr double kMinDepth = 1e-4;  // as the tracer: nearer hits are ignored

// Nearest hit that radiosity sees (no_radiosity objects are skipped).
inline bool radiosity_hit(const Intersector& geometry, const Ray& ray, Hit& hit) {
    double t_min = kMinDepth;
    for (int i = 0; i < 64; ++i) {
        if (!geometry.intersect(ray, t_min, std::numeric_limits<double>::infinity(), hit, Query::All))
            return false;
        if (!hit.no_radiosity) return true;
        t_min = hit.t;
    }
    return false;
}

// The default for rays landing where no element is: they count for nothing.
struct IgnoreUnmeshed {
    void operator()(const Hit&, const glm::dvec3&, double, long, const glm::dvec3&) const {}
};

// Which hits a gather evaluates for itself (on_unmeshed) rather than sharing among the
// vertices of the element they land on.
struct HitEvaluation {
    bool every_hit = false;    // all of them, not only those where no element is
    bool find_element = true;  // with every_hit: look for the element under the hit
};

// The default for rays that started inside solid matter (SceneMesh::solids): counted as any
// other ray (false: not handled).
struct KeepInside {
    bool operator()(const glm::dvec3&, double) const { return false; }
};

// One ray of weight w: on_hit(element, unknown, share, t) for each vertex of the element it
// lands on (barycentric share of w), on_miss(direction, w) when it escapes,
// on_unmeshed(hit, direction, w, element, barycentric) when it lands on a surface without
// elements (element -1), or on any surface as `evaluation` says.
template <class OnHit, class OnMiss, class OnUnmeshed = IgnoreUnmeshed,
          class OnInside = KeepInside>
void trace_ray(const SceneMesh& mesh, const Intersector& geometry, const glm::dvec3& origin,
               const glm::dvec3& dir, double w, OnHit&& on_hit, OnMiss&& on_miss,
               OnUnmeshed&& on_unmeshed = {}, OnInside&& on_inside = {},
               const HitEvaluation& evaluation = {}) {
    Hit hit;
    if (!radiosity_hit(geometry, Ray{origin, dir}, hit)) {
        on_miss(dir, w);
        return;
    }
    if (glm::dot(hit.normal, dir) > 0 && mesh.solids.count(hit.object) && on_inside(dir, w))
        return;
    glm::dvec3 bary(0);
    const long e = !evaluation.every_hit || evaluation.find_element
                       ? mesh.find(origin, dir, hit.t, 1e-4 + 1e-7 * hit.t, hit.object, bary)
                       : -1;
    if (e < 0 || evaluation.every_hit) {
        on_unmeshed(hit, dir, w, e, bary);
        return;
    }
    const MeshElement& el = mesh.elements[size_t(e)];
    const uint32_t side = seen_side(el, hit.normal, -dir);
    for (int k = 0; k < 3; ++k)
        if (bary[k] > 0) on_hit(e, 2 * el.v[k] + side, w * bary[k], hit.t);
}

struct IgnoreStratum {
    void operator()(int, int, int) const {}
};

// `rays` stratified cosine-weighted rays (rounded to a square) from `origin` about the unit
// `normal`, deterministic for `seed`, each of weight 1/rays. on_stratum(i, j, cells) comes
// before the ray of stratum i (in sin^2 theta) and j (in phi) of cells x cells.
template <class OnHit, class OnMiss, class OnUnmeshed = IgnoreUnmeshed,
          class OnStratum = IgnoreStratum, class OnInside = KeepInside>
void cast_rays(const SceneMesh& mesh, const Intersector& geometry, const glm::dvec3& origin,
               const glm::dvec3& normal, uint64_t seed, int rays, OnHit&& on_hit,
               OnMiss&& on_miss, OnUnmeshed&& on_unmeshed = {}, OnStratum&& on_stratum = {},
               OnInside&& on_inside = {}, const HitEvaluation& evaluation = {}) {
    const int cells = std::max(1, int(std::lround(std::sqrt(double(rays)))));
    const double w = 1.0 / (cells * cells);
    SampleRng rng(seed);
    for (int i = 0; i < cells; ++i)
        for (int j = 0; j < cells; ++j) {
            const glm::dvec3 dir =
                cosine_direction(normal, (i + rng.uniform()) / cells, (j + rng.uniform()) / cells);
            on_stratum(i, j, cells);
            trace_ray(mesh, geometry, origin, dir, w, on_hit, on_miss, on_unmeshed, on_inside,
                      evaluation);
        }
}

}  // namespace lumen::render::radiosity
