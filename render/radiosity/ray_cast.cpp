// Ray-cast form factor estimators.
#include "render/radiosity/ray_cast.hpp"

#include <cmath>
#include <numbers>
#include <random>

#include <glm/geometric.hpp>

#include "render/radiosity/form_factor.hpp"

namespace lumen::render::radiosity {

void tangent_frame(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b) {
    // Frisvad-style frame without the singularity at n = -z (Duff et al. 2017).
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double c = n.x * n.y * a;
    t = {1 + sign * n.x * n.x * a, sign * c, -sign * n.x};
    b = {c, sign + n.y * n.y * a, -n.y};
}

glm::dvec3 cosine_direction(const glm::dvec3& n, double u1, double u2) {
    glm::dvec3 t, b;
    tangent_frame(n, t, b);
    const double r = std::sqrt(u1), phi = 2 * std::numbers::pi * u2;
    const double z = std::sqrt(std::max(0.0, 1 - u1));
    return r * std::cos(phi) * t + r * std::sin(phi) * b + z * n;
}

namespace {

// Stratified samples: ray k of `rays` uses a jittered cell of a sqrt(rays)-square grid for
// the position and independent uniforms for the direction.
struct Sampler {
    std::mt19937_64 rng;
    std::uniform_real_distribution<double> uni{0.0, 1.0};
    int side;
    explicit Sampler(uint64_t seed, int rays)
        : rng(seed), side(std::max(1, int(std::sqrt(double(rays))))) {}
    void position(int k, double& u1, double& u2) {
        const int cell = k % (side * side);
        u1 = ((cell % side) + uni(rng)) / side;
        u2 = ((cell / side) + uni(rng)) / side;
    }
    double next() { return uni(rng); }
};

}  // namespace

Estimate ray_cast(const Patch& from, const Patch& to, int rays, uint64_t seed,
                  const Visibility& visible) {
    if (from.degenerate() || to.degenerate() || rays <= 0) return {};
    Sampler s(seed, rays);
    long hits = 0;
    for (int k = 0; k < rays; ++k) {
        double u1, u2;
        s.position(k, u1, u2);
        const glm::dvec3 o = sample_point(from, u1, u2);
        const glm::dvec3 d = cosine_direction(from.normal, s.next(), s.next());
        const double t = intersect(to, o, d);
        if (t > 0 && (!visible || visible(o, o + t * d))) ++hits;
    }
    const double f = double(hits) / rays;
    return {f, std::sqrt(f * (1 - f) / rays)};
}

NearestPatch brute_force_nearest(const std::vector<Patch>& patches, long skip) {
    return [&patches, skip](const glm::dvec3& o, const glm::dvec3& d) -> long {
        double best = INFINITY;
        long hit = -1;
        for (size_t j = 0; j < patches.size(); ++j) {
            if (long(j) == skip) continue;
            const double t = intersect(patches[j], o, d);
            if (t > 0 && t < best) best = t, hit = long(j);
        }
        // A patch seen from behind occludes but receives nothing: its back is not the
        // surface the unknown describes (scoring it would break reciprocity).
        if (hit >= 0 && glm::dot(patches[size_t(hit)].normal, d) >= 0) return -1;
        return hit;
    };
}

std::vector<double> ray_cast_row(const std::vector<Patch>& patches, size_t i, int rays,
                                 uint64_t seed, const NearestPatch& nearest, double* escaped) {
    std::vector<double> row(patches.size(), 0.0);
    const Patch& from = patches[i];
    if (escaped) *escaped = 0;
    if (from.degenerate() || rays <= 0) return row;
    Sampler s(seed, rays);
    long misses = 0;
    for (int k = 0; k < rays; ++k) {
        double u1, u2;
        s.position(k, u1, u2);
        const glm::dvec3 o = sample_point(from, u1, u2);
        const glm::dvec3 d = cosine_direction(from.normal, s.next(), s.next());
        const long hit = nearest(o, d);
        if (hit >= 0 && size_t(hit) < patches.size()) row[hit] += 1.0 / rays;  // i: curved self
        else ++misses;  // the background, or an occluder that is not a patch
    }
    if (escaped) *escaped = double(misses) / rays;
    return row;
}

std::vector<double> ray_cast_row(const std::vector<Patch>& patches, size_t i, int rays,
                                 uint64_t seed, double* escaped) {
    // Flat patches cannot see themselves, so the source is left out of the search.
    return ray_cast_row(patches, i, rays, seed, brute_force_nearest(patches, long(i)), escaped);
}

double point_to_patch_visible(const glm::dvec3& x, const glm::dvec3& n, const Patch& target,
                              int samples, uint64_t seed, const Visibility& visible) {
    const double f = point_to_polygon(x, n, target);
    if (f <= 0 || !visible || samples <= 0) return f;
    Sampler s(seed, samples);
    int seen = 0;
    for (int k = 0; k < samples; ++k) {
        double u1, u2;
        s.position(k, u1, u2);
        if (visible(x, sample_point(target, u1, u2))) ++seen;
    }
    return f * seen / samples;
}

}  // namespace lumen::render::radiosity
