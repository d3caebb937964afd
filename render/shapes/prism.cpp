// prism, traced as POV-Ray traces it: the object-space ray is normalised, the caps are tested
// only when the ray is not parallel to them (|D.y| >= 1e-10) and the walls only when it is
// not parallel to the sweep; each wall is the root w in [0, 1] of the segment's cubic met by
// the ray's plane through the sweep direction (linear) or through the apex (conic).
#include <algorithm>
#include <atomic>
#include <cmath>

#include <glm/geometric.hpp>

#include "render/polynomial.hpp"
#include "render/shapes/prism.hpp"
#include "scene/spline_segments.hpp"

namespace lumen::render {

namespace {

constexpr double kParallel = 1e-10;

// The box of the outline swept between the heights (for conic, the outline scaled by each).
Aabb sweep_box(const Curve& c, double h1, double h2, bool conic) {
    Aabb box;
    if (!conic) {
        box.expand(glm::dvec3(c.lo.x, h1, c.lo.y));
        box.expand(glm::dvec3(c.hi.x, h2, c.hi.y));
        return box;
    }
    for (double h : {h1, h2}) {
        box.expand(glm::dvec3(c.lo.x * h, h, c.lo.y * h));
        box.expand(glm::dvec3(c.hi.x * h, h, c.hi.y * h));
    }
    return box;
}

Aabb padded(Aabb b) {
    const glm::dvec3 pad = 1e-9 * (glm::dvec3(1) + glm::abs(b.lo) + glm::abs(b.hi));
    return {b.lo - pad, b.hi + pad};
}

// A hit being kept: the object distance k along the unit direction, and its normal. The
// caller's range is (t_min, ...) in its ray's units, k = t len: a hit is beyond t_min when
// k / len is, which k > t_min len need not tell (a search from a hit found the same hit again).
struct Nearest {
    double k_min, k, t_min, len;
    glm::dvec3 normal{0};
    bool found = false;
    void offer(double at, const glm::dvec3& n) {
        if (!(at > k_min && at < k && at / len > t_min)) return;
        k = at;
        normal = n;
        found = true;
    }
};

template <class Best>
void hit_caps(const PrismShape& s, const glm::dvec3& P, const glm::dvec3& D, Best& best) {
    if (s.open || std::abs(D.y) < kParallel) return;
    for (double H : {s.h2, s.h1}) {
        if (s.conic && std::abs(H) <= kParallel) continue;
        const double k = (H - P.y) / D.y;
        if (!(k > best.k_min && k < best.k)) continue;
        glm::dvec2 q(P.x + k * D.x, P.z + k * D.z);
        if (s.conic) q /= H;
        if (inside_curve(s.curve, q)) best.offer(k, {0, H == s.h2 ? 1 : -1, 0});
    }
}

// The wall normal for a root: the outline's right-hand normal, turned to face out; a cone's
// gets the slope of its ruling (POV-Ray's y = -(x n.x + z n.z) / y at the hit).
glm::dvec3 wall_normal(const PrismShape& s, const CurveSegment& seg, double w, const glm::dvec3& hit) {
    glm::dvec2 t = seg.tangent(w);
    if (t == glm::dvec2(0)) t = seg.at(1) - seg.at(0);  // a cusp: the chord's normal
    glm::dvec3 n(t.y, 0, -t.x);
    if (!s.conic) return seg.outward * n;
    n.y = std::abs(hit.y) > kParallel ? -(hit.x * n.x + hit.z * n.z) / hit.y : 0;
    return (hit.y < 0 ? -seg.outward : seg.outward) * n;
}

template <class Best>
void hit_walls(const PrismShape& s, const glm::dvec3& P, const glm::dvec3& D, Best& best) {
    if (std::abs(D.x) < kParallel && std::abs(D.z) < kParallel) return;
    const SlabRay slab(P, D);
    // The plane holding the ray and the sweep direction (linear) or the apex (conic), as
    // u * x + v * z + k0 = 0 over the outline's points (x, z).
    const double u = s.conic ? P.z * D.y - P.y * D.z : D.z;
    const double v = s.conic ? P.y * D.x - P.x * D.y : -D.x;
    const double k0 = s.conic ? P.x * D.z - P.z * D.x : D.x * P.z - D.z * P.x;
    for (const CurveSegment& seg : s.curve.segments) {
        if (!s.conic) {
            const Aabb rect{{seg.lo.x, s.h1, seg.lo.y}, {seg.hi.x, s.h2, seg.hi.y}};
            if (!slab.hits(padded(rect), best.k_min, best.k)) continue;
        }
        double cx[4], cz[4], c[4];
        seg.coefficients(0, cx);
        seg.coefficients(1, cz);
        for (int i = 0; i < 4; ++i) c[i] = u * cx[i] + v * cz[i];
        c[0] += k0;
        double w[3];
        const int n = solve_significant_in(c, 3, 0, 1, w);
        for (int i = 0; i < n; ++i) {
            const glm::dvec2 q = seg.at(w[i]);
            double k;
            if (!s.conic) {
                k = std::abs(D.x) > kParallel ? (q.x - P.x) / D.x : (q.y - P.z) / D.z;
            } else {
                const double den = D.x - q.x * D.y;
                k = std::abs(den) >= kParallel ? (q.x * P.y - P.x) / den
                                                : (q.y * P.y - P.z) / (D.z - q.y * D.y);
            }
            const double y = P.y + k * D.y;
            if (!(y >= s.h1 && y <= s.h2) || !(k > best.k_min && k < best.k)) continue;
            best.offer(k, wall_normal(s, seg, w[i], P + k * D));
        }
    }
}

// Every hit of one ray beyond k_min, in the order they are offered (caps, then walls segment
// by segment): the nearest in any narrower range is the first of the least k in it, as
// Nearest would keep it.
struct AllHits {
    static constexpr int kMax = 32;
    double k_min = 0, k = 0;  // k: the far limit, fixed
    int count = 0;
    bool overflow = false;
    double at[kMax];
    glm::dvec3 normal[kMax];
    void reset(double near, double far) {
        k_min = near;
        k = far;
        count = 0;
        overflow = false;
    }
    void offer(double a, const glm::dvec3& n) {
        if (!(a > k_min && a < k)) return;
        if (count == kMax) {
            overflow = true;
            return;
        }
        at[count] = a;
        normal[count++] = n;
    }
    // The nearest in (lo, hi) in the units of a ray of direction length len (see Nearest).
    bool nearest(double lo, double hi, double len, double& best_t, glm::dvec3& best_n) const {
        bool found = false;
        for (int i = 0; i < count; ++i)
            if (const double t = at[i] / len; t > lo && t < hi) {
                hi = t;
                best_t = t;
                best_n = normal[i];
                found = true;
            }
        return found;
    }
};

// The last ray's hits on the last prism a thread traced. CSG lists or walks a member's hits by
// asking again from each one: 95% of advanced/grenadine's prism asks came right after one for
// the same prism and ray.
struct LastPrismRay {
    uint64_t prism = 0;  // its serial: addresses are reused by later prisms
    glm::dvec3 o{0}, d{0};
    AllHits hits;
};

}  // namespace

PrismShape make_prism(const scene::Prism& p) {
    PrismShape out;
    out.h1 = std::min(p.height1, p.height2);
    out.h2 = std::max(p.height1, p.height2);
    out.conic = p.conic;
    out.open = p.open;
    const scene::SplineWalk walk = scene::prism_walk(p.spline, p.points);
    bool finite = std::isfinite(out.h1) && std::isfinite(out.h2);
    for (const glm::dvec2& q : p.points) finite = finite && std::isfinite(q.x) && std::isfinite(q.y);
    if (!finite || !p.closed || !walk.closed || walk.starts.empty()) return out;
    out.curve = make_curve(p.spline, p.points, walk.starts, true);
    out.box = sweep_box(out.curve, out.h1, out.h2, out.conic);
    static std::atomic<uint64_t> next_serial{1};
    out.serial = next_serial++;
    out.valid = true;
    return out;
}

bool intersect(const PrismShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h) {
    if (!s.valid) return false;
    const double len = glm::length(r.d);
    if (!(len > 0)) return false;
    const glm::dvec3 D = r.d / len, P = r.o;
    thread_local LastPrismRay last;
    if (!(last.prism == s.serial && last.o == r.o && last.d == r.d && !last.hits.overflow &&
          last.hits.k_min <= tmin * len)) {
        double enter, exit;
        if (!SlabRay(P, D).hits(padded(s.box), tmin * len, Aabb::inf, enter, exit)) {
            last.prism = 0;
            return false;
        }
        if (std::abs(D.y) < kParallel && (P.y < s.h1 || P.y > s.h2)) return false;
        // Every hit out to the box's far side, kept for the asks that follow on this ray.
        const double far = exit * (1 + 1e-9) + 1e-9;
        last.prism = s.serial;
        last.o = r.o;
        last.d = r.d;
        last.hits.reset(tmin * len, far);
        hit_caps(s, P, D, last.hits);
        hit_walls(s, P, D, last.hits);
        if (last.hits.overflow) {  // too many to keep: the nearest alone
            last.prism = 0;
            Nearest best{tmin * len, std::min(tmax * len, far), tmin, len};
            hit_caps(s, P, D, best);
            hit_walls(s, P, D, best);
            if (!best.found) return false;
            h.t = best.k / len;
            h.normal = best.normal;
            return true;
        }
    }
    double t = 0;
    glm::dvec3 normal;
    if (!last.hits.nearest(tmin, tmax, len, t, normal)) return false;
    h.t = t;
    h.normal = normal;
    return true;
}

bool inside(const PrismShape& s, const glm::dvec3& p) {
    if (!s.valid || !(p.y >= s.h1 && p.y < s.h2)) return false;  // POV's half-open heights
    glm::dvec2 q(p.x, p.z);
    if (s.conic) {
        if (std::abs(p.y) <= kParallel) return false;
        q /= p.y;
    }
    return inside_curve(s.curve, q);
}

Aabb bounds(const PrismShape& s) { return s.box; }

}  // namespace lumen::render
