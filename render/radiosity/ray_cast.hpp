// Monte Carlo form factors by cosine-weighted ray casting from uniform points on the source,
// and Wallace's point-to-patch estimate (Lambert's exact
// unoccluded value times a sampled visible fraction). Occlusion comes from a callback so the
// tracer's own BVH can answer it later.
#pragma once
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/vec3.hpp>

#include "render/radiosity/patch.hpp"

namespace lumen::render::radiosity {

// True when the segment from `from` to `to` is unobstructed. An empty function means
// "nothing blocks".
using Visibility = std::function<bool(const glm::dvec3& from, const glm::dvec3& to)>;

struct Estimate {
    double value = 0;
    double sigma = 0;  // binomial standard error of `value`
};

// F_from→to from `rays` cosine-weighted rays (stratified over the source), counting a ray
// when it crosses `to` and `visible(origin, hit)` holds. Deterministic for a given seed.
Estimate ray_cast(const Patch& from, const Patch& to, int rays, uint64_t seed,
                  const Visibility& visible = {});

// One row F_i* by gathering: each ray scores on the nearest patch it hits (brute force over
// `patches`, so the patches occlude each other). `escaped` receives the fraction of rays
// that hit nothing (the background's form factor) when non-null.
std::vector<double> ray_cast_row(const std::vector<Patch>& patches, size_t i, int rays,
                                 uint64_t seed, double* escaped = nullptr);

// The nearest patch along a ray (index into the caller's patch list), or -1: the hook for
// the tracer's BVH, whose scene may also hold occluders that are not patches.
using NearestPatch = std::function<long(const glm::dvec3& origin, const glm::dvec3& dir)>;

// The same row with a caller-supplied ray query instead of the brute-force search.
std::vector<double> ray_cast_row(const std::vector<Patch>& patches, size_t i, int rays,
                                 uint64_t seed, const NearestPatch& nearest,
                                 double* escaped = nullptr);

// Brute-force NearestPatch over `patches` (skipping `skip`); the reference for tests. A
// nearest patch seen from behind gives -1 (it occludes, but its back receives nothing).
NearestPatch brute_force_nearest(const std::vector<Patch>& patches, long skip = -1);

// Lambert's exact value times the fraction of `samples` jittered points on `target` that are
// visible from x (Wallace et al. 1989).
double point_to_patch_visible(const glm::dvec3& x, const glm::dvec3& n, const Patch& target,
                              int samples, uint64_t seed, const Visibility& visible);

// A cosine-distributed unit direction around unit normal n from two uniform numbers.
glm::dvec3 cosine_direction(const glm::dvec3& n, double u1, double u2);

// An orthonormal pair (t, b) completing unit n to a right-handed frame.
void tangent_frame(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b);

}  // namespace lumen::render::radiosity
