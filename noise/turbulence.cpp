// Turbulence and DTurbulence: octaves of noise, each at lambda times the frequency and omega
// times the amplitude of the one before (lambda and omega are POV's single-precision values
// promoted to double; the caller rounds them when it reads them).
#include <algorithm>

#include "noise/noise.hpp"

namespace lumen::noise {
namespace {

int octave_count(const scene::TurbulenceParams& params) { return std::clamp(params.octaves, 1, 10); }

}  // namespace

double turbulence(const glm::dvec3& p, const scene::TurbulenceParams& params,
                  Generator generator) {
    const int octaves = octave_count(params);
    const double lambda = params.lambda, omega = params.omega;
    double l = lambda, o = omega;
    if (generator == Generator::Original) {
        double v = noise(p, generator);
        for (int i = 2; i <= octaves; ++i) {
            v += o * noise(p * l, generator);
            if (i < octaves) l *= lambda, o *= omega;
        }
        return v;
    }
    // Generators 2 and 3 centre each octave; only the first is clamped.
    double v = std::clamp(2.0 * noise(p, generator) - 0.5, 0.0, 1.0);
    for (int i = 2; i <= octaves; ++i) {
        v += o * (2.0 * noise(p * l, generator) - 0.5);
        if (i < octaves) l *= lambda, o *= omega;
    }
    return v;
}

glm::dvec3 dturbulence(const glm::dvec3& p, const scene::TurbulenceParams& params) {
    const int octaves = octave_count(params);
    const double lambda = params.lambda, omega = params.omega;
    double l = lambda, o = omega;
    glm::dvec3 r = dnoise(p);
    for (int i = 2; i <= octaves; ++i) {
        const glm::dvec3 d = dnoise(p * l);
        r.x += o * d.x;
        r.y += o * d.y;
        r.z += o * d.z;
        if (i < octaves) l *= lambda, o *= omega;
    }
    return r;
}

}  // namespace lumen::noise
