// superellipsoid: POV-Ray's piecewise search. Its tolerances decide which grazing rays hit,
// so they are POV-Ray's: 1e-10 counts as zero, 20 iterations per root, depths over 1e-4.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "render/shapes/superellipsoid.hpp"

namespace lumen::render {

namespace {

constexpr double kZero = 1e-10;
constexpr double kEpsilon = 1e-10;
constexpr double kBoxMin = -1.01, kBoxMax = 1.01;  // the search box (a little over the shape)
constexpr double kBoundHuge = 2e10;
constexpr double kMaxDistance = 1e7;
constexpr int kMaxIterations = 20;
constexpr int kPlaneCount = 9;
constexpr double kPlanes[kPlaneCount][3] = {{1, 1, 0}, {1, -1, 0}, {1, 0, 1}, {1, 0, -1},
                                            {0, 1, 1}, {0, 1, -1}, {1, 0, 0}, {0, 1, 0},
                                            {0, 0, 1}};

// x^e, by multiplication for the integer powers 0..6 (as POV-Ray computes them), and for
// the larger integer powers up to 64 by squaring (POV-Ray calls pow: the same value within a
// few ulps, at a fraction of the cost; advanced/glasschess's e = 0.05 gives 2/e = 40).
double power(double x, double e) {
    if (!(e >= 0 && e <= 64) || e != std::floor(e)) return std::pow(x, e);  // inf, NaN too
    switch (const int i = int(e)) {
        case 0: return 1;
        case 1: return x;
        case 2: return x * x;
        case 3: return x * x * x;
        case 4: { double b = x * x; return b * b; }
        case 5: { double b = x * x; return b * b * x; }
        case 6: { double b = x * x; return b * b * b; }
        default: {
            double result = 1;
            for (int k = i; k > 0; k >>= 1, x *= x)
                if (k & 1) result *= x;
            return result;
        }
    }
}

// (x^e + y^e)^(1/e), computed from the larger so it neither overflows nor underflows.
double combine(double x, double y, double e) {
    double g = 0;
    if (x > y) {
        g = 1 + power(y / x, e);
        if (g != 1) g = power(g, 1 / e);
        g *= x;
    } else if (y != 0) {
        g = 1 + power(x / y, e);
        if (g != 1) g = power(g, 1 / e);
        g *= y;
    }
    return g;
}

// The ray's span in the search box, POV-Ray's slab order and EPSILON tests.
bool clip_to_box(const glm::dvec3& p, const glm::dvec3& d, double& dmin, double& dmax) {
    if (std::fabs(d.x) > kEpsilon) {
        if (d.x > kEpsilon) {
            dmin = (kBoxMin - p.x) / d.x;
            dmax = (kBoxMax - p.x) / d.x;
            if (dmax < kEpsilon) return false;
        } else {
            dmax = (kBoxMin - p.x) / d.x;
            if (dmax < kEpsilon) return false;
            dmin = (kBoxMax - p.x) / d.x;
        }
        if (dmin > dmax) return false;
    } else {
        if (p.x < kBoxMin || p.x > kBoxMax) return false;
        dmin = -kBoundHuge;
        dmax = kBoundHuge;
    }
    for (int a = 1; a < 3; ++a) {
        if (std::fabs(d[a]) > kEpsilon) {
            double lo = (kBoxMin - p[a]) / d[a], hi = (kBoxMax - p[a]) / d[a];
            if (d[a] < 0) std::swap(lo, hi);
            if (hi < dmax) {
                if (hi < kEpsilon) return false;
                if (lo > dmin) {
                    if (lo > hi) return false;
                    dmin = lo;
                } else if (dmin > hi) {
                    return false;
                }
                dmax = hi;
            } else if (lo > dmin) {
                if (lo > dmax) return false;
                dmin = lo;
            }
        } else if (p[a] < kBoxMin || p[a] > kBoxMax) {
            return false;
        }
    }
    return true;
}

struct Search {
    const SuperellipsoidShape& s;
    double f(const glm::dvec3& p) const { return superellipsoid_value(s, p); }

    // Secant and midpoint together, keeping a bracket, until |F| < 1e-10 or 20 rounds.
    glm::dvec3 root(double v0, glm::dvec3 p0, double v1, glm::dvec3 p1) const {
        for (int i = 0; i < kMaxIterations; ++i) {
            if (std::fabs(v0) < kZero) return p0;
            if (std::fabs(v1) < kZero) return p1;
            const glm::dvec3 p2 = p0 + (std::fabs(v0) / std::fabs(v1 - v0)) * (p1 - p0);
            const double v2 = f(p2);
            const glm::dvec3 p3 = p0 + 0.5 * (p1 - p0);
            const double v3 = f(p3);
            if (v2 * v3 < 0) {
                v0 = v2; p0 = p2;
                v1 = v3; p1 = p3;
            } else if (std::fabs(v2) < std::fabs(v3)) {
                if (v0 * v2 < 0) { v1 = v2; p1 = p2; } else { v0 = v2; p0 = p2; }
            } else {
                if (v0 * v3 < 0) { v1 = v3; p1 = p3; } else { v0 = v3; p0 = p3; }
            }
        }
        return std::fabs(v0) < std::fabs(v1) ? p0 : p1;
    }

    // No sign change over [t0, t1]: secant steps from t0 looking for a grazing crossing.
    bool graze(const glm::dvec3& o, const glm::dvec3& d, double t0, glm::dvec3 p0, double v0,
               double t1, double& k) const {
        double dt0 = t0, dt1 = t0 + 0.0001 * (t1 - t0), step = 0;
        const double max_step = t1 - t0;
        for (int i = 0; dt0 < t1 && i < kMaxIterations; ++i) {
            const glm::dvec3 p1 = o + dt1 * d;
            const double v1 = f(p1);
            if (v0 * v1 < 0) {
                k = glm::length(root(v0, p0, v1, p1) - o);
                return true;
            }
            if (std::fabs(v1) < kZero) {
                k = dt1;
                return true;
            }
            if ((v0 > 0 && v1 > v0) || (v0 < 0 && v1 < v0) || v1 == v0) return false;
            step = v1 * (dt1 - dt0) / (v1 - v0);
            if (std::fabs(step) > max_step) return false;
            v0 = v1;
            p0 = p1;
            dt0 = dt1;
            dt1 -= step;
        }
        return false;
    }
};

}  // namespace

SuperellipsoidShape make_superellipsoid(const scene::Superellipsoid& s) {
    SuperellipsoidShape out;
    out.power = {2 / s.e, s.e / s.n, 2 / s.n};
    // e = 0 gives 2/0 = inf (a box-like cross section), kept; NaN or negative powers are not.
    out.valid = std::isfinite(s.e) && std::isfinite(s.n) && s.e >= 0 && s.n >= 0 &&
                !(s.e == 0 && s.n == 0) && !std::isnan(out.power.x) && !std::isnan(out.power.z);
    return out;
}

double superellipsoid_value(const SuperellipsoidShape& s, const glm::dvec3& p) {
    return combine(combine(std::fabs(p.x), std::fabs(p.y), s.power.x), std::fabs(p.z),
                   s.power.z) - 1;
}

int superellipsoid_hits(const SuperellipsoidShape& s, const glm::dvec3& o, const glm::dvec3& d,
                        double len, double* ks, double nearest_beyond) {
    double t1, t2;
    if (!clip_to_box(o, d, t1, t2) || t2 < kDepthSuperellipsoid) return 0;
    t1 = std::max(t1, kDepthSuperellipsoid);
    // The cut points: the box span and the planes crossed inside it (widened for rounding).
    double dists[kPlaneCount + 2] = {t1, t2};
    int cnt = 2;
    const double widen = kEpsilon * (t2 - t1), lo = t1 - widen, hi = t2 + widen;
    for (const auto& pl : kPlanes) {
        const double dn = d.x * pl[0] + d.y * pl[1] + d.z * pl[2];
        if (std::fabs(dn) < kEpsilon) continue;
        const double t = -(o.x * pl[0] + o.y * pl[1] + o.z * pl[2]) / dn;
        if (t >= lo && t <= hi) dists[cnt++] = t;
    }
    for (int i = 1; i < cnt; ++i)  // insertion sort: at most 11 values
        for (int j = i; j > 0 && dists[j] < dists[j - 1]; --j) std::swap(dists[j], dists[j - 1]);
    // A depth POV-Ray accepts (in world units).
    auto valid = [len](double k) { return k / len > kDepthSuperellipsoid && k / len < kMaxDistance; };
    const Search search{s};
    int n = 0;
    glm::dvec3 p0 = o + dists[0] * d;
    double v0 = search.f(p0);
    if (std::fabs(v0) < kZero && valid(dists[0])) ks[n++] = dists[0];
    // The nearest hit beyond `nearest_beyond` so far: a piece starting past it (a root found
    // in a piece lies within it, within rounding) holds none nearer.
    double nearest = std::numeric_limits<double>::infinity();
    const auto note = [&](int from) {
        for (int j = from; j < n; ++j)
            if (ks[j] > nearest_beyond && ks[j] < nearest) nearest = ks[j];
    };
    note(0);
    for (int i = 1; i < cnt; ++i) {
        if (nearest < dists[i - 1] * (1 - 1e-9) - 1e-12) break;
        const int before = n;
        const glm::dvec3 p1 = o + dists[i] * d;
        const double v1 = search.f(p1);
        if (std::fabs(v1) < kZero) {
            if (valid(dists[i])) ks[n++] = dists[i];
        } else if (v0 * v1 < 0) {
            const double k = glm::length(search.root(v0, p0, v1, p1) - o);
            if (valid(k)) ks[n++] = k;
        } else {
            double k;
            if (search.graze(o, d, dists[i - 1], p0, v0, dists[i], k)) {
                if (!valid(k)) break;  // POV-Ray stops the search there
                ks[n++] = k;
                // A grazing ray leaves again before dists[i] (F has the same sign at both
                // ends). POV-Ray loses that exit; it is found here, so CSG and inside tests
                // see an entry and an exit. The first hit, and so a plain image, is POV's.
                const double after = k + 1e-6 * (dists[i] - dists[i - 1]);
                const glm::dvec3 pa = o + after * d;
                const double va = search.f(pa);
                if (after < dists[i] && va * v1 < 0) {
                    const double exit = glm::length(search.root(va, pa, v1, p1) - o);
                    if (valid(exit)) ks[n++] = exit;
                }
            }
        }
        v0 = v1;
        p0 = p1;
        note(before);
    }
    return n;
}

bool intersect(const SuperellipsoidShape& s, const LocalRay& r, double tmin, double tmax,
               ShapeHit& h) {
    if (!s.valid) return false;
    const double len = glm::length(r.d);
    if (!(len > 0) || !std::isfinite(len)) return false;
    double ks[kMaxSuperellipsoidHits];
    const int n = superellipsoid_hits(s, r.o, r.d / len, len, ks, tmin * len);
    double best = tmax;
    bool found = false;
    for (int i = 0; i < n; ++i) {
        const double t = ks[i] / len;
        if (t > tmin && t < best) { best = t; found = true; }
    }
    if (!found) return false;
    h.t = best;
    // POV-Ray's gradient, written with ratios so it stays finite near the edges.
    glm::dvec3 p = r.at(best);
    const glm::dvec3& e = s.power;
    double ratio = 0, z2n = 0;
    if (p.z != 0) {
        z2n = power(std::fabs(p.z), e.z);
        p.z = z2n / p.z;
    }
    if (std::fabs(p.x) > std::fabs(p.y)) {
        ratio = power(std::fabs(p.y / p.x), e.x);
        p.y = p.y != 0 ? (1 - z2n) * ratio / p.y : 0;
        p.x = (1 - z2n) / p.x;
    } else if (p.y != 0) {
        ratio = power(std::fabs(p.x / p.y), e.x);
        p.x = p.x != 0 ? (1 - z2n) * ratio / p.x : 0;
        p.y = (1 - z2n) / p.y;
    }
    if (p.z != 0) p.z *= 1 + ratio;
    h.normal = p;
    const double n2 = glm::dot(p, p);
    if (!(n2 > 0) || !std::isfinite(n2)) h.normal = {0, 0, 1};
    return true;
}

bool inside(const SuperellipsoidShape& s, const glm::dvec3& p) {
    return s.valid && superellipsoid_value(s, p) < kEpsilon;
}

Aabb bounds(const SuperellipsoidShape& s) {
    if (!s.valid) return {};
    return {glm::dvec3(kBoxMin), glm::dvec3(kBoxMax)};
}

}  // namespace lumen::render
