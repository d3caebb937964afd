// The patterns that are noise at the point: bozo, spotted and bumps (the same value, different
// default colour maps), dents, and the fixed-octave sums granite and wrinkles.
#include <algorithm>
#include <cmath>

#include "render/patterns/noise_kinds.hpp"

namespace lumen::render {

double evaluate(const pattern::Bozo&, const glm::dvec3& p, const scene::Pattern& pat) {
    return noise::noise(p, generator_of(pat));
}
double evaluate(const pattern::Spotted&, const glm::dvec3& p, const scene::Pattern& pat) {
    return noise::noise(p, generator_of(pat));
}
double evaluate(const pattern::Bumps&, const glm::dvec3& p, const scene::Pattern& pat) {
    return noise::noise(p, generator_of(pat));
}

double evaluate(const pattern::Dents&, const glm::dvec3& p, const scene::Pattern& pat) {
    const double n = noise::noise(p, generator_of(pat));
    return n * n * n;
}

// Six octaves of folded noise at four times the scale: |0.5 - n| for the original generator,
// min(|1 - 2n|, 0.5) for the others.
double evaluate(const pattern::Granite&, const glm::dvec3& p, const scene::Pattern& pat) {
    const noise::Generator gen = generator_of(pat);
    const glm::dvec3 base = 4.0 * p;
    double sum = 0, freq = 1;
    for (int i = 0; i < 6; ++i, freq *= 2) {
        const double n = noise::noise(base * freq, gen);
        const double t = gen == noise::Generator::Original ? std::fabs(0.5 - n)
                                                           : std::min(std::fabs(1 - 2 * n), 0.5);
        sum += t / freq;
    }
    return sum;
}

// Ten octaves (lambda 2, omega 0.5), every one clamped for the generators after the first
// (unlike turbulence, which clamps only its first octave); half the sum.
double evaluate(const pattern::Wrinkles&, const glm::dvec3& p, const scene::Pattern& pat) {
    const noise::Generator gen = generator_of(pat);
    auto octave = [gen](const glm::dvec3& q) {
        const double n = noise::noise(q, gen);
        return gen == noise::Generator::Original ? n : std::clamp(2 * n - 0.5, 0.0, 1.0);
    };
    double sum = octave(p), lambda = 2, omega = 0.5;
    for (int i = 1; i < 10; ++i, lambda *= 2, omega *= 0.5) sum += omega * octave(p * lambda);
    return sum / 2;
}

}  // namespace lumen::render
