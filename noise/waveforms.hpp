// POV-Ray's periodic helpers, used by the pattern wave types, the noise patterns (wood, agate,
// ripples, waves, spiral2) and the ripples/waves normals. They are written the way POV
// computes them, so results agree to the last bit.
#pragma once
#include <cmath>
#include <numbers>

namespace lumen::noise {

// sin(2π v), through the fraction of v quantised the way POV's cycloidal() does; odd in v.
inline double cycloidal(double v) {
    constexpr double two_pi = 2 * std::numbers::pi;
    if (v >= 0) return std::sin((v - std::floor(v)) * 50000.0 / 50000.0 * two_pi);
    const double w = -v;
    return -std::sin((w - std::floor(w)) * 50000.0 / 50000.0 * two_pi);
}

// The triangle wave: 0 at integers, 1 at half-integers, linear in between.
inline double triangle_wave(double v) {
    const double o = v >= 0 ? v - std::floor(v) : v + 1.0 + std::floor(std::fabs(v));
    return o >= 0.5 ? 2.0 * (1.0 - o) : 2.0 * o;
}

}  // namespace lumen::noise
