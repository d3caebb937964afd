#include "render/patterns/normal_forms.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "noise/noise.hpp"
#include "noise/waveforms.hpp"

namespace lumen::render {
namespace {

const double kHalfDiagonal = std::sqrt(3.0) / 2;

// The scene-wide noise settings a normal uses. POV's defaults until the scene's
// noise_generator and number_of_waves reach patterns (with the noise patterns); dents,
// ripples and waves are reported unsupported until then (scene/normal_forms.hpp).
noise::Generator generator_of(const scene::Pattern& pattern) {
    return noise::resolve_generator(pattern.noise_generator, 2);
}
int wave_count(const scene::Pattern&) { return 10; }

// The quilt's cross-section: a cubic Bezier curve from 0 to 1 with control points control0
// and control1 (POV-Ray's manual: 0 and 0 give a straight slope, 1 and 1 an S curve).
double quilt_profile(double t, double c0, double c1) {
    const double it = 1 - t;
    return t * t * t + 3 * t * t * it * c1 + 3 * t * it * it * c0;
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

void add_form(const pattern::Bumps&, const scene::Normal& normal, const glm::dvec3& p, glm::dvec3& n) {
    n += normal.amount * noise::dnoise(p);
}

// The magnitude follows the pattern's generator; the direction is always the original
// lattice's vector noise.
void add_form(const pattern::Dents&, const scene::Normal& normal, const glm::dvec3& p, glm::dvec3& n) {
    const double s = noise::noise(p, generator_of(normal.pattern));
    n += (s * s * s * normal.amount) * noise::dnoise(p);
}

// Every component is taken absolute after the octave's scaling, so wrinkles lean the normal
// towards +x+y+z on the whole (as POV's do).
void add_form(const pattern::Wrinkles&, const scene::Normal& normal, const glm::dvec3& p,
              glm::dvec3& n) {
    glm::dvec3 sum(0);
    double scale = 1;
    for (int octave = 0; octave < 10; ++octave, scale *= 2)
        sum += glm::abs(noise::dnoise(p * scale) / scale);
    n += normal.amount * sum;
}

void add_form(const pattern::Ripples&, const scene::Normal& normal, const glm::dvec3& p,
              glm::dvec3& n) {
    const scene::Pattern& pat = normal.pattern;
    add_waves(normal, p, n,
              [&](const noise::Wave&, double length) { return length * pat.frequency + pat.phase; },
              [](const noise::Wave&) { return 1.0; });
}

void add_form(const pattern::Waves&, const scene::Normal& normal, const glm::dvec3& p, glm::dvec3& n) {
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
void add_form(const pattern::Quilted& k, const scene::Normal& normal, const glm::dvec3& p,
              glm::dvec3& n) {
    const glm::dvec3 d = p - glm::floor(p) - glm::dvec3(0.5);
    const double t = quilt_profile(glm::length(d), k.control0, k.control1);
    n += normal.amount * (d * (t / kHalfDiagonal));
}

}  // namespace lumen::render
