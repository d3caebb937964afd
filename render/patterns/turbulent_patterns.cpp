// The patterns that take the pattern's own (classic) turbulence into their formula: marble and
// wood (which POV therefore does not also displace by it), agate (always turbulent, scaled by
// agate_turb) and the spirals (turbulence optional).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "noise/waveforms.hpp"
#include "render/patterns/noise_kinds.hpp"

namespace lumen::render {
namespace {

// Turbulence along x scaled by the classic amount's x, 0 without classic turbulence.
double turbulence_term(const glm::dvec3& p, const scene::Pattern& pat) {
    const scene::TurbulenceParams* t = pat.steps.classic_turbulence();
    if (!t || t->amount.x == 0) return 0;
    return t->amount.x * noise::turbulence(p, *t, generator_of(pat));
}

// The spiral's value before waves: height plus distance from the z axis plus the arm angle.
double spiral(int arms, const glm::dvec3& p, const scene::Pattern& pat) {
    using std::numbers::pi;
    const double rad = std::sqrt(p.x * p.x + p.y * p.y);
    double phi = 0;
    if (rad != 0) phi = p.x < 0 ? 3 * pi / 2 - std::asin(p.y / rad) : pi / 2 + std::asin(p.y / rad);
    return p.z + rad + arms * phi / (2 * pi) + turbulence_term(p, pat);
}

}  // namespace

double evaluate(const pattern::Marble&, const glm::dvec3& p, const scene::Pattern& pat) {
    return p.x + turbulence_term(p, pat);
}

// Rings around the z axis, the turbulence folded in through a cycloidal offset.
double evaluate(const pattern::Wood&, const glm::dvec3& p, const scene::Pattern& pat) {
    double px = p.x, py = p.y;
    const scene::TurbulenceParams* t = pat.steps.classic_turbulence();
    if (t && (t->amount.x != 0 || t->amount.y != 0)) {
        const glm::dvec3 d = noise::dturbulence(p, *t);
        px = p.x + noise::cycloidal((p.x + d.x) * t->amount.x);
        py = p.y + noise::cycloidal((p.y + d.y) * t->amount.y);
    }
    return std::sqrt(px * px + py * py);
}

double evaluate(const pattern::Agate& k, const glm::dvec3& p, const scene::Pattern& pat) {
    const double t = k.agate_turb * noise::turbulence(p, classic_turbulence_of(pat), generator_of(pat));
    const double n = 0.5 * (noise::cycloidal(1.3 * t + 1.1 * p.z) + 1);
    if (n < 0) return 0;
    return std::pow(std::min(n, 1.0), 0.77);
}

double evaluate(const pattern::Spiral1& k, const glm::dvec3& p, const scene::Pattern& pat) {
    return spiral(k.arms, p, pat);
}

double evaluate(const pattern::Spiral2& k, const glm::dvec3& p, const scene::Pattern& pat) {
    const double rad = std::sqrt(p.x * p.x + p.y * p.y);
    return noise::triangle_wave(rad) + noise::triangle_wave(spiral(k.arms, p, pat));
}

}  // namespace lumen::render
