// The noise internal functions (internal.cpp's table calls them): f_noise3d, f_noise_generator
// and the fractal noises f_hetero_mf, f_ridge and f_ridged_mf, in POV-Ray's order of
// operations.
#include "function/internal_noise.hpp"

#include <algorithm>
#include <climits>
#include <cmath>

#include <glm/vec3.hpp>

#include "noise/noise.hpp"

namespace lumen::fn::detail {

namespace {

// Octave counts (and hetero_mf's power) beyond which POV would loop for minutes or forever
// (an infinite octave count never ends there); lumen stops at this many.
constexpr int kMaxOctaves = 10000;

noise::Generator scene_generator(int g) {
    // POV's Noise() treats every number but 2 and 3 as the original generator.
    return g == 2 ? noise::Generator::RangeCorrected
                  : g == 3 ? noise::Generator::Perlin : noise::Generator::Original;
}
// A generator parameter: int(gen) & 3, so 0 (and 4, 8, ...) is 1 and -1 is 3.
noise::Generator param_generator(double gen) { return scene_generator(to_int(gen) & 3); }
// Noise in [-1, 1].
double snoise(const glm::dvec3& p, noise::Generator g) { return noise::noise(p, g) * 2.0 - 1.0; }

}  // namespace

// C's (int) conversion as x86 does it: out of range (undefined in C++) and NaN give INT_MIN.
int to_int(double v) { return v > -2147483649.0 && v < 2147483648.0 ? int(v) : INT_MIN; }

double noise3d(const glm::dvec3& p, int scene_generator_number) {
    return noise::noise(p, scene_generator(scene_generator_number));
}

double noise_generator(const glm::dvec3& p, const double* params) {
    return noise::noise(p, param_generator(params[0]));
}

// params: H, lacunarity, octaves, offset, T, generator.
double hetero_mf(const glm::dvec3& p, const double* params) {
    const double H = params[0], L = params[1], octaves = params[2], off = params[3];
    const noise::Generator g = param_generator(params[5]);
    glm::dvec3 v = p;
    double signal = snoise(v, g) + off;
    v *= L;
    const double w = std::pow(L, -H);
    double e = w;
    const int power = std::min(to_int(params[4]), kMaxOctaves);
    for (int i = 1; i < octaves && i <= kMaxOctaves; ++i) {
        // The increment scaled by f^-H and by the signal so far int(T) times.
        double inc = (snoise(v, g) + off) * e;
        for (int k = power; k > 0; --k) inc *= signal;
        signal += inc;
        v *= L;
        e *= w;
    }
    const double rest = octaves - to_int(octaves);
    if (rest != 0.0) signal += rest * ((snoise(v, g) + off) * e) * signal;
    return signal;
}

// params: lambda, octaves, omega, offset, ridge, generator.
double ridge(const glm::dvec3& p, const double* params) {
    const double lambda = params[0], omega = params[2], off = params[3], rdg = params[4];
    const noise::Generator g = param_generator(params[5]);
    const int octaves = to_int(params[1]);
    const double rscale = 1.0 / std::max(rdg, 1.0 - rdg);
    const double scale = 1.0 / std::max(off, 1.0 - off);
    const double rest = params[1] - double(octaves);
    auto ridged = [&](const glm::dvec3& q) {
        return std::fabs(noise::noise(q, g) - rdg) * rscale;
    };
    double value = ridged(p) - off, total = 1.0, l = lambda, o = omega;
    // Each octave scales the original point by the running frequency.
    for (int i = 2; i <= std::min(octaves, kMaxOctaves); ++i) {
        value += o * (ridged(p * l) - off);
        total += o;
        l *= lambda;
        o *= omega;
    }
    if (0.0 != rest) {
        value += o * (ridged(p * l) - off) * rest;
        total += o * rest;
    }
    return value * scale / total;
}

// params: H, lacunarity, octaves, offset, gain, generator.
double ridged_mf(const glm::dvec3& p, const double* params) {
    const double H = params[0], L = params[1], octaves = params[2], off = params[3];
    const double gain = params[4];
    const noise::Generator g = param_generator(params[5]);
    glm::dvec3 v = p;
    auto ridged = [&] {
        double s = snoise(v, g);
        if (s < 0.0) s = -s;
        s = off - s;
        return s * s;
    };
    double signal = ridged(), result = signal, freq = 1.0;
    // POV fills a table of freq^-H on a function's first call and keeps it with the declared
    // function, so its later calls with another H, lacunarity or more octaves reuse (or
    // overrun) it. Here each call uses its own parameters, which gives POV's first-call values.
    for (int i = 1; i < octaves && i <= kMaxOctaves; ++i) {
        v *= L;
        freq *= L;
        double weight = signal * gain;
        if (weight > 1.0) weight = 1.0;
        if (weight < 0.0) weight = 0.0;
        signal = ridged() * weight;
        result += signal * std::pow(freq, -H);
    }
    return result;
}

}  // namespace lumen::fn::detail
