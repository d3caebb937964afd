// The grid is built coarse to fine: a coarse cell proved empty needs no finer test. The
// enclosures are widened at every step by far more than double rounding, so that they hold
// the floating-point orbits that the march computes, not only the exact ones; the maybe-cells
// are dilated by one so that the traversal's own rounding cannot miss one.
#include "render/shapes/julia_grid.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

#include "render/interval.hpp"
#include "render/shapes/julia_fractal.hpp"

namespace lumen::render {

namespace {

constexpr int kCoarse = 16, kRefine = 4;  // 64^3 cells
constexpr double kSlack = 1e-12;          // relative widening per iteration

// True when every point of the box escapes before max_iteration (iterate()'s test on
// z_0 .. z_N-1).
bool box_escapes(const JuliaFractalShape& s, const glm::dvec3& lo, const glm::dvec3& hi) {
    Interval z[4] = {{lo.x, hi.x}, {lo.y, hi.y}, {lo.z, hi.z}, {0, 0}};
    z[3] = (1 / s.slice.w) * (Interval{s.slice_distance, s.slice_distance} - s.slice.x * z[0] -
                              s.slice.y * z[1] - s.slice.z * z[2]);
    const bool cube = s.function == scene::JuliaFunction::Cube;
    const bool hyper = s.algebra == scene::JuliaAlgebra::Hypercomplex;
    for (int i = 0; i < s.iterations; ++i) {
        Interval sqs[4] = {square(z[0]), square(z[1]), square(z[2]), square(z[3])};
        if (sqs[0].lo + sqs[1].lo + sqs[2].lo + sqs[3].lo > s.exit_value * (1 + 1e-9))
            return true;
        const Interval d = sqs[1] + sqs[2] + sqs[3];
        Interval next[4];
        if (hyper) {  // sqr, and cube, which POV-Ray also squares (render/shapes/hypercomplex.cpp)
            next[0] = sqs[0] + sqs[3] - sqs[1] - sqs[2];
            next[1] = 2 * (z[0] * z[1] - z[2] * z[3]);
            next[2] = 2 * (z[0] * z[2] - z[3] * z[1]);
            next[3] = 2 * (z[0] * z[3] + z[1] * z[2]);
        } else if (cube) {
            const Interval t = 3 * sqs[0] - d;
            next[0] = z[0] * (sqs[0] - 3 * d);
            for (int k = 1; k < 4; ++k) next[k] = t * z[k];
        } else {
            next[0] = sqs[0] - d;
            for (int k = 1; k < 4; ++k) next[k] = 2 * (z[0] * z[k]);
        }
        double big = 0;
        for (int k = 0; k < 4; ++k) {
            next[k] = next[k] + Interval{s.c[k], s.c[k]};
            big = std::max({big, std::fabs(next[k].lo), std::fabs(next[k].hi)});
        }
        if (!(big < 1e100)) return false;  // no longer decidable
        const double widen = kSlack * big + 1e-300;
        for (int k = 0; k < 4; ++k) z[k] = {next[k].lo - widen, next[k].hi + widen};
    }
    return false;
}

}  // namespace

std::shared_ptr<const JuliaGrid> JuliaGrid::build(const JuliaFractalShape& s) {
    const bool polynomial = s.algebra == scene::JuliaAlgebra::Quaternion ||
                            s.function == scene::JuliaFunction::Sqr ||
                            s.function == scene::JuliaFunction::Cube;
    if (!polynomial || s.iterations <= 0) return nullptr;
    auto grid = std::make_shared<JuliaGrid>();
    const int n = kCoarse * kRefine;
    const double r = std::sqrt(s.radius2);
    grid->n_ = n;
    grid->lo_ = -r;
    grid->cell_ = 2 * r / n;
    std::vector<uint8_t> maybe(size_t(n) * n * n, 0);
    auto corner = [&](int x, int y, int z, int size) {
        return glm::dvec3(-r) + grid->cell_ * glm::dvec3(x, y, z) * double(size);
    };
    // Coarse layers shared out among threads (each writes its own cells).
    auto layers = [&](int first, int stride) {
    for (int cz = first; cz < kCoarse; cz += stride)
        for (int cy = 0; cy < kCoarse; ++cy)
            for (int cx = 0; cx < kCoarse; ++cx) {
                const double big = grid->cell_ * kRefine;
                const glm::dvec3 lo = corner(cx, cy, cz, kRefine);
                if (box_escapes(s, lo, lo + big)) continue;
                for (int fz = 0; fz < kRefine; ++fz)
                    for (int fy = 0; fy < kRefine; ++fy)
                        for (int fx = 0; fx < kRefine; ++fx) {
                            const int x = cx * kRefine + fx, y = cy * kRefine + fy,
                                      z = cz * kRefine + fz;
                            const glm::dvec3 flo = corner(x, y, z, 1);
                            if (!box_escapes(s, flo, flo + grid->cell_))
                                maybe[size_t((z * n + y) * n + x)] = 1;
                        }
            }
    };
    const int threads = int(std::clamp(std::thread::hardware_concurrency(), 1u, 8u));
    std::vector<std::thread> helpers;
    for (int t = 1; t < threads; ++t) helpers.emplace_back(layers, t, threads);
    layers(0, threads);
    for (std::thread& t : helpers) t.join();
    grid->maybe_.assign(maybe.size(), 0);
    int* blo = grid->box_lo_;
    int* bhi = grid->box_hi_;
    blo[0] = blo[1] = blo[2] = n;
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                if (!maybe[size_t((z * n + y) * n + x)]) continue;
                const int c[3] = {x, y, z};
                for (int k = 0; k < 3; ++k) {
                    blo[k] = std::min(blo[k], std::max(c[k] - 1, 0));
                    bhi[k] = std::max(bhi[k], std::min(c[k] + 2, n));
                }
                for (int dz = std::max(z - 1, 0); dz <= std::min(z + 1, n - 1); ++dz)
                    for (int dy = std::max(y - 1, 0); dy <= std::min(y + 1, n - 1); ++dy)
                        for (int dx = std::max(x - 1, 0); dx <= std::min(x + 1, n - 1); ++dx)
                            grid->maybe_[size_t((dz * n + dy) * n + dx)] = 1;
            }
    return grid;
}

bool JuliaGrid::may_contain(const glm::dvec3& p) const {
    const glm::dvec3 g = (p - lo_) / cell_;
    if (!(g.x >= 0 && g.y >= 0 && g.z >= 0 && g.x < n_ && g.y < n_ && g.z < n_)) return true;
    return at(int(g.x), int(g.y), int(g.z));
}

// The parameter (0 at a, 1 at b) where the segment a-b enters its first maybe-cell, or
// HUGE_VAL when it meets none. Amanatides-Woo within the maybe-cells' box.
double JuliaGrid::first_maybe(const glm::dvec3& a, const glm::dvec3& b) const {
    const glm::dvec3 ga = (a - lo_) / cell_, d = (b - a) / cell_;
    double t0 = 0, t1 = 1;
    for (int k = 0; k < 3; ++k) {
        if (box_lo_[k] >= box_hi_[k]) return HUGE_VAL;  // no maybe-cell at all
        if (d[k] == 0) {
            if (ga[k] < box_lo_[k] || ga[k] > box_hi_[k]) return HUGE_VAL;
            continue;
        }
        double u = (box_lo_[k] - ga[k]) / d[k], v = (box_hi_[k] - ga[k]) / d[k];
        if (u > v) std::swap(u, v);
        t0 = std::max(t0, u);
        t1 = std::min(t1, v);
    }
    if (!(t0 <= t1)) return HUGE_VAL;
    const glm::dvec3 p = ga + t0 * d;
    int cell[3], step[3];
    double next[3], delta[3];
    for (int k = 0; k < 3; ++k) {
        cell[k] = std::clamp(int(std::floor(p[k])), box_lo_[k], box_hi_[k] - 1);
        step[k] = d[k] > 0 ? 1 : (d[k] < 0 ? -1 : 0);
        delta[k] = step[k] != 0 ? 1 / std::fabs(d[k]) : HUGE_VAL;
        const double boundary = cell[k] + (step[k] > 0 ? 1 : 0);
        next[k] = step[k] != 0 ? t0 + (boundary - p[k]) / d[k] : HUGE_VAL;
    }
    double entry = t0;
    for (int guard = 0; guard < 3 * n_ + 3; ++guard) {
        if (at(cell[0], cell[1], cell[2])) return entry;
        const int k = next[0] < next[1] ? (next[0] < next[2] ? 0 : 2) : (next[1] < next[2] ? 1 : 2);
        if (next[k] > t1) return HUGE_VAL;
        cell[k] += step[k];
        if (cell[k] < box_lo_[k] || cell[k] >= box_hi_[k]) return HUGE_VAL;
        entry = next[k];
        next[k] += delta[k];
    }
    return entry;  // not reached: a segment crosses at most 3n cells
}

bool JuliaGrid::maybe_span(const glm::dvec3& a, const glm::dvec3& b, double& last) const {
    last = 1;
    for (int k = 0; k < 3; ++k)
        if (!std::isfinite(a[k]) || !std::isfinite(b[k])) return true;  // the march decides
    if (first_maybe(a, b) == HUGE_VAL) return false;
    // The same walk from b: where it enters the last maybe-cell the segment leaves it.
    const double back = first_maybe(b, a);
    if (back != HUGE_VAL) last = std::clamp(1 - back, 0.0, 1.0);
    return true;
}

double JuliaGrid::occupied_fraction() const {
    if (maybe_.empty()) return 1;
    return double(std::count(maybe_.begin(), maybe_.end(), 1)) / double(maybe_.size());
}

}  // namespace lumen::render
