// ripples and waves: concentric waves from the scene's wave sources (noise::waves), each at the
// pattern's frequency and phase, which POV applies here and again in the usual wave step.
#include <cmath>

#include "noise/waveforms.hpp"
#include "render/patterns/noise_kinds.hpp"

namespace lumen::render {
namespace {

int wave_count(const scene::Pattern& pat) { return pat.globals ? pat.globals->number_of_waves : 10; }

// Distance to the source; POV takes 1 at the source itself.
double distance_to(const glm::dvec3& p, const glm::dvec3& source) {
    const glm::dvec3 d = p - source;
    const double l = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    return l == 0 ? 1.0 : l;
}

}  // namespace

double evaluate(const pattern::Ripples&, const glm::dvec3& p, const scene::Pattern& pat) {
    const auto waves = noise::waves(wave_count(pat));
    double sum = 0;
    for (const noise::Wave& w : waves)
        sum += noise::cycloidal(distance_to(p, w.source) * pat.frequency + pat.phase);
    return 0.5 * (1.0 + sum / double(waves.size()));
}

// Each source at its own frequency, its amplitude inversely proportional to it; can leave [0, 1].
double evaluate(const pattern::Waves&, const glm::dvec3& p, const scene::Pattern& pat) {
    const auto waves = noise::waves(wave_count(pat));
    double sum = 0;
    for (const noise::Wave& w : waves)
        sum += noise::cycloidal(distance_to(p, w.source) * pat.frequency * w.frequency + pat.phase) /
               w.frequency;
    return 0.2 * (2.5 + sum / double(waves.size()));
}

}  // namespace lumen::render
