#include "render/patterns/normal_forms.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "noise/noise.hpp"
#include "noise/waveforms.hpp"
#include "render/patterns/noise_kinds.hpp"

namespace lumen::render {
namespace {

const double kHalfDiagonal = std::sqrt(3.0) / 2;

// global_settings { number_of_waves }, which ripples and waves share with their pigments.
int wave_count(const scene::Pattern& pattern) {
    return pattern.globals ? pattern.globals->number_of_waves : 10;
}

// The quilt's cross-section: a cubic Bezier curve from 0 to 1 with control points control0
// and control1 (POV-Ray's manual: 0 and 0 give a straight slope, 1 and 1 an S curve).
double quilt_profile(double t, double c0, double c1) {
    const double it = 1 - t;
    return t * t * t + 3 * t * t * it * c1 + 3 * t * it * it * c0;
}

// The crackle cell point nearest to p: the cells around p's (its own and every offset of -2..2
// with at most one component of magnitude 2, x outermost), each with the point PatternRands
// gives its hash, nearest by the facets metric: the squared distance for 2, the sum of |d|^m
// otherwise, and for 1 the sum of the signed differences (POV's facets leave the absolute
// values out there: measured, its facets are then nearly a grid).
glm::dvec3 nearest_cell_point(const glm::dvec3& p, double metric) {
    constexpr double kEpsilon = 1e-10;
    const int hx = int(std::floor(p.x - kEpsilon)), hy = int(std::floor(p.y - kEpsilon)),
              hz = int(std::floor(p.z - kEpsilon));
    double best = 0;
    glm::dvec3 nearest(0);
    bool first = true;
    for (int dx = -2; dx <= 2; ++dx)
        for (int dy = -2; dy <= 2; ++dy)
            for (int dz = -2; dz <= 2; ++dz) {
                if ((std::abs(dx) == 2) + (std::abs(dy) == 2) + (std::abs(dz) == 2) > 1) continue;
                const int a = hx + dx, b = hy + dy, c = hz + dz;
                const int q = noise::hash3d(a, b, c);
                const glm::dvec3 point(a + noise::pattern_rand(q), b + noise::pattern_rand(q + 1),
                                       c + noise::pattern_rand(q + 2));
                const glm::dvec3 d = point - p;
                double dist;
                if (metric == 2) dist = glm::dot(d, d);
                else if (metric == 1) dist = d.x + d.y + d.z;
                else dist = std::pow(std::fabs(d.x), metric) + std::pow(std::fabs(d.y), metric) +
                            std::pow(std::fabs(d.z), metric);
                if (first || dist < best) best = dist, nearest = point, first = false;
            }
    return nearest;
}

// Concentric waves about each source: `index(i, length)` is the wave's phase at the distance,
// `weight(i)` divides the wave's amplitude (POV: 1 for ripples, the source's frequency for
// waves); the sum is averaged over the sources.
template <class Index, class Weight>
void add_waves(const scene::Normal& normal, const glm::dvec3& p, glm::dvec3& n,
               const Index& index, const Weight& weight) {
    const auto waves = noise::waves(wave_count(normal.pattern));
    const double count = double(waves.size());
    for (size_t i = 0; i < waves.size(); ++i) {
        const glm::dvec3 d = p - waves[i].source;
        double length = glm::length(d);
        if (length == 0) length = 1;
        const double scalar = noise::cycloidal(index(waves[i], length)) * normal.amount / weight(waves[i]);
        n += (scalar / (length * count)) * d;
    }
}

}  // namespace

void apply_form(const pattern::Bumps&, const scene::Normal& normal, const glm::dvec3& p, glm::dvec3& n) {
    n += normal.amount * noise::dnoise(p);
}

// The magnitude follows the pattern's generator; the direction is always the original
// lattice's vector noise.
void apply_form(const pattern::Dents&, const scene::Normal& normal, const glm::dvec3& p, glm::dvec3& n) {
    const double s = noise::noise(p, generator_of(normal.pattern));
    n += (s * s * s * normal.amount) * noise::dnoise(p);
}

// Every component is taken absolute after the octave's scaling, so wrinkles lean the normal
// towards +x+y+z on the whole (as POV's do).
void apply_form(const pattern::Wrinkles&, const scene::Normal& normal, const glm::dvec3& p,
              glm::dvec3& n) {
    glm::dvec3 sum(0);
    double scale = 1;
    for (int octave = 0; octave < 10; ++octave, scale *= 2)
        sum += glm::abs(noise::dnoise(p * scale) / scale);
    n += normal.amount * sum;
}

void apply_form(const pattern::Ripples&, const scene::Normal& normal, const glm::dvec3& p,
              glm::dvec3& n) {
    const scene::Pattern& pat = normal.pattern;
    add_waves(normal, p, n,
              [&](const noise::Wave&, double length) { return length * pat.frequency + pat.phase; },
              [](const noise::Wave&) { return 1.0; });
}

void apply_form(const pattern::Waves&, const scene::Normal& normal, const glm::dvec3& p, glm::dvec3& n) {
    const scene::Pattern& pat = normal.pattern;
    add_waves(normal, p, n,
              [&](const noise::Wave& w, double length) {
                  return length * pat.frequency * w.frequency + pat.phase;
              },
              [](const noise::Wave& w) { return w.frequency; });
}

// Each unit cube is one quilt: the normal leans away from the cube's centre by the profile of
// the distance to it, over half the cube's diagonal (the factor measured against povray
// renders, exact to the pixel for any amount, controls and scale).
void apply_form(const pattern::Quilted& k, const scene::Normal& normal, const glm::dvec3& p,
              glm::dvec3& n) {
    const glm::dvec3 d = p - glm::floor(p) - glm::dvec3(0.5);
    const double t = quilt_profile(glm::length(d), k.control0, k.control1);
    n += normal.amount * (d * (t / kHalfDiagonal));
}

void apply_form(const pattern::Facets& k, const scene::Normal&, const glm::dvec3& p, glm::dvec3& n) {
    const double len = glm::length(n);
    if (len > 0) n /= len;
    const double scale = k.size < 1e-6 ? 1e6 : 1 / k.size;
    if (k.coords == 0) {
        n = nearest_cell_point(n * scale, k.metric);  // the unwarp normalises it
        return;
    }
    const glm::dvec3 tilt = k.coords * noise::dnoise(nearest_cell_point(p * scale, k.metric));
    n += tilt - glm::dot(tilt, n) * n;
}

}  // namespace lumen::render
