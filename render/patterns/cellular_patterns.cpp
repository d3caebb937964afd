// The cell patterns: cells (one random value per unit cube) and crackle (Worley's cellular
// pattern over one feature point per unit cube). Both draw from POV's PatternRands through the
// lattice hash, so the cells and feature points are the same in every scene.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "render/patterns/noise_kinds.hpp"

namespace lumen::render {
namespace {

constexpr double kEpsilon = 1e-10;

// floor(v) as a lattice coordinate; only its value mod 4096 matters, so far-away (and
// non-finite) coordinates just need a defined conversion.
int cell_of(double v) {
    const double f = std::floor(v);
    if (!(std::fabs(f) < 1e18)) return 0;
    return int(std::int64_t(f) & 4095);
}

glm::dvec3 feature_point(int a, int b, int c) {
    const int q = noise::hash3d(a, b, c);
    return {a + noise::pattern_rand(q), b + noise::pattern_rand(q + 1),
            c + noise::pattern_rand(q + 2)};
}

double distance(const glm::dvec3& p, const glm::dvec3& f, double metric) {
    const double dx = f.x - p.x, dy = f.y - p.y, dz = f.z - p.z;
    if (metric == 2) return dx * dx + dy * dy + dz * dz;
    if (metric == 1) return std::fabs(dx) + std::fabs(dy) + std::fabs(dz);
    return std::pow(std::fabs(dx), metric) + std::pow(std::fabs(dy), metric) +
           std::pow(std::fabs(dz), metric);
}

// Distance back from the metric's own measure (squared for 2, none for 1).
double unmeasured(double d, double metric) {
    if (metric == 2) return std::sqrt(d);
    if (metric == 1) return d;
    return std::pow(d, 1 / metric);
}

// The three smallest distances seen so far, in order, and the feature point of the first
// smallest (a later tie keeps the earlier, as POV's strict comparisons do). The distances
// pass through a min/max chain rather than branches: which of 27 is near is unpredictable.
class NearestThree {
public:
    void add(double d, const glm::dvec3& f) {
        if (d < d_[0]) f_ = f;
        const double up0 = std::max(d_[0], d);
        d_[0] = std::min(d_[0], d);
        const double up1 = std::max(d_[1], up0);
        d_[1] = std::min(d_[1], up0);
        d_[2] = std::min(d_[2], up1);
    }
    double third() const { return d_[2]; }
    const double* d() const { return d_; }
    const glm::dvec3& nearest() const { return f_; }

private:
    double d_[3] = {INFINITY, INFINITY, INFINITY};
    glm::dvec3 f_{0};
};

// The feature points of the home cube and its 26 neighbours, x outermost. Neighbouring
// samples mostly share a home cube, so each thread keeps the last ones' in a small table
// indexed by the cube (several crackle patterns, as in several media, take turns in it).
const std::array<glm::dvec3, 27>& inner_feature_points(const int (&h)[3]) {
    struct Entry {
        int home[3] = {0, 0, 0};
        bool valid = false;
        std::array<glm::dvec3, 27> points;
    };
    constexpr unsigned kEntries = 64;
    thread_local std::array<Entry, kEntries> cache;
    const unsigned slot =
        (unsigned(h[0]) * 73856093u ^ unsigned(h[1]) * 19349663u ^ unsigned(h[2]) * 83492791u) % kEntries;
    Entry& e = cache[slot];
    if (!e.valid || e.home[0] != h[0] || e.home[1] != h[1] || e.home[2] != h[2]) {
        int n = 0;
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dz = -1; dz <= 1; ++dz)
                    e.points[n++] = feature_point(h[0] + dx, h[1] + dy, h[2] + dz);
        std::copy(h, h + 3, e.home);
        e.valid = true;
    }
    return e.points;
}

}  // namespace

double evaluate(const pattern::Cells&, const glm::dvec3& p, const scene::Pattern&) {
    const int h = noise::hash3d(cell_of(p.x + kEpsilon), cell_of(p.y + kEpsilon),
                                cell_of(p.z + kEpsilon));
    return std::min(noise::pattern_rand(h), 1.0);
}

// POV searches the home cube's neighbours within 1, and those 2 away along one axis (81
// cubes). A neighbour 2 away lies at least its gap along that axis from p, so its face of
// nine cubes is searched only when that could beat the third distance found in the inner 27
// (which leaves the result as POV's, up to exact ties).
double evaluate(const pattern::Crackle& k, const glm::dvec3& p, const scene::Pattern& pat) {
    const double fx = std::floor(p.x - kEpsilon), fy = std::floor(p.y - kEpsilon),
                 fz = std::floor(p.z - kEpsilon);
    if (!(std::fabs(fx) < 1e9 && std::fabs(fy) < 1e9 && std::fabs(fz) < 1e9)) return 0;
    const int h[3] = {int(fx), int(fy), int(fz)};
    const double m = k.metric;
    NearestThree near;
    const std::array<glm::dvec3, 27>& inner = inner_feature_points(h);
    double d27[27];
    if (m == 2) {  // the usual metric, in a loop the compiler vectorises
        for (int i = 0; i < 27; ++i) {
            const double dx = inner[i].x - p.x, dy = inner[i].y - p.y, dz = inner[i].z - p.z;
            d27[i] = dx * dx + dy * dy + dz * dz;
        }
    } else {
        for (int i = 0; i < 27; ++i) d27[i] = distance(p, inner[i], m);
    }
    for (int i = 0; i < 27; ++i) near.add(d27[i], inner[i]);
    auto visit = [&](int a, int b, int c) {
        const glm::dvec3 f = feature_point(a, b, c);
        near.add(distance(p, f, m), f);
    };
    const double frac[3] = {p.x - fx, p.y - fy, p.z - fz};
    for (int axis = 0; axis < 3; ++axis)
        for (int side : {-2, 2}) {
            // The gap from p to the face's cubes along this axis, as the metric measures it.
            const double gap = side < 0 ? frac[axis] + 1 : 2 - frac[axis];
            const double bound = m == 2 ? gap * gap : m == 1 ? gap : std::pow(gap, m);
            if (m > 0 && bound > near.third() * (1 + 1e-9)) continue;
            for (int i = -1; i <= 1; ++i)
                for (int j = -1; j <= 1; ++j) {
                    int c[3];
                    c[axis] = h[axis] + side;
                    c[(axis + 1) % 3] = h[(axis + 1) % 3] + i;
                    c[(axis + 2) % 3] = h[(axis + 2) % 3] + j;
                    visit(c[0], c[1], c[2]);
                }
        }
    if (k.solid) return std::clamp(noise::noise(near.nearest(), generator_of(pat)), 0.0, 1.0);
    double d[3] = {near.d()[0], near.d()[1], near.d()[2]};
    if (k.offset != 0) {
        const double o = m == 2 ? k.offset * k.offset : m == 1 ? k.offset : std::pow(k.offset, m);
        for (double& di : d) di += o;
    }
    const double v = k.form.x * unmeasured(d[0], m) + k.form.y * unmeasured(d[1], m) +
                     k.form.z * unmeasured(d[2], m);
    return std::clamp(v, 0.0, 1.0);
}

}  // namespace lumen::render
