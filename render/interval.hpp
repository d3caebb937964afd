// Interval arithmetic on doubles for conservative bounds (render/shapes/poly_bounds.cpp,
// render/shapes/julia_grid.cpp). Rounding is not directed: callers widen their results by a
// margin far above double rounding.
#pragma once
#include <algorithm>
#include <cmath>

namespace lumen::render {

struct Interval {
    double lo, hi;
};

inline Interval operator+(Interval a, Interval b) { return {a.lo + b.lo, a.hi + b.hi}; }
inline Interval operator-(Interval a, Interval b) { return {a.lo - b.hi, a.hi - b.lo}; }
inline Interval operator*(double k, Interval a) {
    return k >= 0 ? Interval{k * a.lo, k * a.hi} : Interval{k * a.hi, k * a.lo};
}
inline Interval operator*(Interval a, Interval b) {
    const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    return {std::min({p[0], p[1], p[2], p[3]}), std::max({p[0], p[1], p[2], p[3]})};
}
inline Interval square(Interval a) {
    const double l = a.lo * a.lo, h = a.hi * a.hi;
    if (a.lo <= 0 && a.hi >= 0) return {0, std::max(l, h)};
    return {std::min(l, h), std::max(l, h)};
}
// a^k for k >= 0 (std::pow at the ends).
inline Interval power(Interval a, int k) {
    if (k == 0) return {1, 1};
    const double l = std::pow(a.lo, k), h = std::pow(a.hi, k);
    if (k % 2 == 1) return {l, h};
    if (a.lo <= 0 && a.hi >= 0) return {0, std::max(l, h)};
    return {std::min(l, h), std::max(l, h)};
}

}  // namespace lumen::render
