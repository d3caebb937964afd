// sphere_sweep: per segment, the s-ranges where the ray meets the moving sphere (roots of the
// discriminant D(s)), the extremes of t_in and t_out over each range (its ends and the roots
// of the envelope polynomial P(s)), then the first boundary of the union of those intervals.
// Every polynomial is solved by Bernstein subdivision (sphere_sweep_roots.hpp), which misses
// no simple root and returns no NaN; a grazing range too thin to bracket is a miss.
#include "render/shapes/sphere_sweep.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "render/polynomial.hpp"
#include "render/shapes/sphere_sweep_roots.hpp"

namespace lumen::render {

namespace {

using Poly = SweepPoly;

// Component `axis` of a vector polynomial, or a scalar one.
Poly poly_of(const glm::dvec3* v, int n, int axis) {
    Poly p;
    p.n = n;
    for (int i = 0; i <= n; ++i) p.c[i] = v[i][axis];
    return p;
}
Poly poly_of(const double* v, int n) {
    Poly p;
    p.n = n;
    for (int i = 0; i <= n; ++i) p.c[i] = v[i];
    return p;
}

// x . y for vector polynomials given per axis.
Poly dot(const Poly (&x)[3], const Poly (&y)[3]) {
    return add(add(x[0] * y[0], 1, x[1] * y[1]), 1, x[2] * y[2]);
}

template <class V> V at(const V* c, int n, double s) {
    V v = c[n];
    for (int i = n - 1; i >= 0; --i) v = v * s + c[i];
    return v;
}

// Where along the ray one end of a segment's interval lies, and the surface normal there.
struct Bound {
    double t;
    glm::dvec3 normal;
};
struct Span {
    Bound in, out;
};

// The ray meets sphere s of the segment at t_in(s) <= t_out(s) (t from o), if at all.
struct SphereAt {
    const SweepSegment& seg;
    const glm::dvec3 &o, &d;
    double a;  // d . d
    bool roots(double s, double& t_in, double& t_out) const {
        const glm::dvec3 v = o - at(seg.c, seg.degree, s);
        const double r = at(seg.r, seg.degree, s);
        const double b = glm::dot(d, v), disc = b * b - a * (glm::dot(v, v) - r * r);
        const double q = std::sqrt(std::max(disc, 0.0));
        t_in = (-b - q) / a;
        t_out = (-b + q) / a;
        return std::isfinite(t_in) && std::isfinite(t_out);
    }
    glm::dvec3 normal(double s, double t) const {
        const glm::dvec3 n = o + t * d - at(seg.c, seg.degree, s);
        return glm::dot(n, n) > 0 ? n : -d;  // a cone's tip hit head on
    }
};

// The segment's intervals along o + t d, appended to `out` (t measured from o).
void segment_spans(const SweepSegment& seg, const glm::dvec3& o, const glm::dvec3& d,
                   std::vector<Span>& out) {
    const int n = seg.degree;
    const double a = glm::dot(d, d);
    // v(s) = o - c(s) per axis, the radius, and c'(s).
    glm::dvec3 vc[4];
    for (int i = 0; i <= n; ++i) vc[i] = i == 0 ? o - seg.c[0] : -seg.c[i];
    const Poly v[3] = {poly_of(vc, n, 0), poly_of(vc, n, 1), poly_of(vc, n, 2)};
    const Poly dv[3] = {derivative(v[0]), derivative(v[1]), derivative(v[2])};  // -c'
    const Poly r = poly_of(seg.r, n);
    const Poly dp[3] = {constant(d.x), constant(d.y), constant(d.z)};
    const Poly b = dot(dp, v);                    // d . v
    const Poly c = add(dot(v, v), -1, r * r);     // |v|^2 - r^2
    const Poly disc = add(b * b, -a, c);          // D = b^2 - a c
    if (!positive_somewhere(disc)) return;        // the ray misses every sphere
    double cuts[Poly::kMax + 2];
    int ncut = 0;
    cuts[ncut++] = 0;
    double roots[Poly::kMax];
    const int nroots = root_candidates(disc, 0, 1, roots, Poly::kMax);
    for (int i = 1; i < nroots; ++i)  // ascending (a handful: insertion)
        for (int j = i; j > 0 && roots[j] < roots[j - 1]; --j) std::swap(roots[j], roots[j - 1]);
    for (int i = 0; i < nroots; ++i)
        if (roots[i] > cuts[ncut - 1] && roots[i] < 1) cuts[ncut++] = roots[i];
    cuts[ncut++] = 1;
    // dg/ds = -2 (N + t k) with N = v . c' + r r' and k = d . c' (c' = -v'): its root
    // t = -N / k put into g, times k^2: P = a N^2 - 2 N b k + c k^2.
    const Poly nn = add(r * derivative(r), -1, dot(v, dv));
    const Poly k = add(Poly{}, -1, dot(dp, dv));
    const Poly env = add(add(constant(a) * nn * nn, -2, nn * b * k), 1, c * k * k);
    const Poly denv = derivative(env);
    const SphereAt sphere{seg, o, d, a};
    for (int i = 0; i + 1 < ncut; ++i) {
        const double s0 = cuts[i], s1 = cuts[i + 1];
        if (!(eval_poly(disc.c, disc.n, 0.5 * (s0 + s1)) > 0)) continue;
        Span span{{1e300, {}}, {-1e300, {}}};
        double s_in = s0, s_out = s0;
        auto consider = [&](double s) {
            double t_in, t_out;
            if (!sphere.roots(s, t_in, t_out)) return;
            if (t_in < span.in.t) span.in.t = t_in, s_in = s;
            if (t_out > span.out.t) span.out.t = t_out, s_out = s;
        };
        consider(s0);
        consider(s1);
        // P = a h_in h_out with h = N + t k: where k vanishes (a ray square to the segment)
        // or D does, h_in and h_out share roots and P only touches 0 there (rounding may
        // lift it clear of 0), so the roots of P' are candidates too (a spare candidate is
        // harmless: only the extremes count).
        for (const Poly* q : {&env, &denv})
            for (int j = 0, m = root_candidates(*q, s0, s1, roots, Poly::kMax); j < m; ++j)
                consider(roots[j]);
        if (!(span.in.t <= span.out.t)) continue;
        span.in.normal = sphere.normal(s_in, span.in.t);
        span.out.normal = sphere.normal(s_out, span.out.t);
        out.push_back(span);
    }
}

// The bounding box of a segment: on each axis, the extremes over [0, 1] of c(s) + r(s) and
// c(s) - r(s) (the sphere of s spans between them whatever the radius's sign), found at the
// ends and at the roots of their derivatives. A small pad covers the roots' rounding.
Aabb segment_box(const SweepSegment& seg) {
    const int n = seg.degree;
    Aabb box;
    for (int axis = 0; axis < 3; ++axis)
        for (double sign : {1.0, -1.0}) {
            Poly f = add(poly_of(seg.c, n, axis), sign, poly_of(seg.r, n));
            const Poly df = derivative(f);
            double at_s[Poly::kMax + 2] = {0, 1};
            const int m = 2 + root_candidates(df, 0, 1, at_s + 2, Poly::kMax);
            for (int k = 0; k < m; ++k) {
                const double v = eval_poly(f.c, f.n, at_s[k]);
                box.lo[axis] = std::min(box.lo[axis], v);
                box.hi[axis] = std::max(box.hi[axis], v);
            }
        }
    const glm::dvec3 pad(1e-9 * (1 + glm::length(box.hi - box.lo)));
    return {box.lo - pad, box.hi + pad};
}

}  // namespace

std::vector<SweepSegment> sweep_segments(const scene::SphereSweep& s) {
    // Power-basis matrices, rows = powers of s, columns = the segment's spheres.
    static constexpr double kBSpline[4][4] = {{1 / 6.0, 4 / 6.0, 1 / 6.0, 0},
                                              {-3 / 6.0, 0, 3 / 6.0, 0},
                                              {3 / 6.0, -6 / 6.0, 3 / 6.0, 0},
                                              {-1 / 6.0, 3 / 6.0, -3 / 6.0, 1 / 6.0}};
    static constexpr double kCatmullRom[4][4] = {{0, 1, 0, 0},
                                                 {-0.5, 0, 0.5, 0},
                                                 {1, -2.5, 2, -0.5},
                                                 {-0.5, 1.5, -1.5, 0.5}};
    std::vector<SweepSegment> out;
    const auto& p = s.spheres;
    const int n = static_cast<int>(p.size());
    if (s.spline == scene::SweepSpline::Linear) {
        for (int i = 0; i + 1 < n; ++i) {
            SweepSegment seg;
            seg.c[0] = p[i].center, seg.c[1] = p[i + 1].center - p[i].center;
            seg.r[0] = p[i].radius, seg.r[1] = p[i + 1].radius - p[i].radius;
            out.push_back(seg);
        }
        return out;
    }
    const auto& m = s.spline == scene::SweepSpline::BSpline ? kBSpline : kCatmullRom;
    for (int i = 0; i + 3 < n; ++i) {
        SweepSegment seg;
        seg.degree = 3;
        for (int k = 0; k < 4; ++k)
            for (int j = 0; j < 4; ++j) {
                seg.c[k] += m[k][j] * p[i + j].center;
                seg.r[k] += m[k][j] * p[i + j].radius;
            }
        out.push_back(seg);
    }
    return out;
}

SphereSweepShape make_sphere_sweep(const scene::SphereSweep& s) {
    SphereSweepShape out;
    out.tolerance = s.tolerance;
    glm::dvec3 lo, hi;
    s.control_box(lo, hi);
    // POV-Ray bounds the sweep by that box: an inverted one (negative radii) is never hit.
    if (s.spheres.empty() || lo.x > hi.x || lo.y > hi.y || lo.z > hi.z) return out;
    std::vector<SweepSegment> segs = sweep_segments(s);
    std::vector<Aabb> boxes;
    for (SweepSegment& seg : segs) {
        seg.box = segment_box(seg);
        if (!seg.box.finite()) return out;
        boxes.push_back(seg.box);
        out.box.expand(seg.box);
    }
    if (segs.empty()) return out;
    out.tree.build(boxes, 2);
    for (uint32_t i : out.tree.order()) out.segments.push_back(segs[i]);
    out.valid = true;
    return out;
}

bool intersect(const SphereSweepShape& s, const LocalRay& r, double tmin, double tmax,
               ShapeHit& h) {
    if (!s.valid) return false;
    tmin = std::max(tmin, s.tolerance);
    thread_local std::vector<Span> spans;
    // From outside, the hit is the nearest interval start past tmin, and a segment whose box
    // starts beyond the nearest start so far cannot come nearer: the traversal is pruned
    // there. An interval holding tmin means the ray starts inside, and then every interval
    // the ray passes within [tmin, tmax] counts (no pruning: the exit may lie behind any).
    auto collect = [&](bool prune) {
        spans.clear();
        bool from_inside = false;
        double far = tmax;
        s.tree.traverse(SlabRay(r.o, r.d), tmin, far, [&](uint32_t i) {
            const SweepSegment& seg = s.segments[i];
            // Solved about the point of the ray nearest the segment, for well-scaled
            // polynomials.
            const double t0 = glm::dot(seg.box.centre() - r.o, r.d) / glm::dot(r.d, r.d);
            const size_t first = spans.size();
            segment_spans(seg, r.at(t0), r.d, spans);
            for (size_t k = first; k < spans.size(); ++k) {
                Span& span = spans[k];
                span.in.t += t0, span.out.t += t0;
                if (span.in.t <= tmin && span.out.t > tmin) from_inside = true;
                if (prune && !from_inside && span.in.t > tmin) far = std::min(far, span.in.t);
            }
        });
        return from_inside;
    };
    if (collect(true)) collect(false);
    std::sort(spans.begin(), spans.end(),
              [](const Span& x, const Span& y) { return x.in.t < y.in.t; });
    // Merged runs of overlapping intervals; the first boundary past tmin is the hit.
    for (size_t i = 0; i < spans.size();) {
        Span run = spans[i++];
        while (i < spans.size() && spans[i].in.t <= run.out.t) {
            if (spans[i].out.t > run.out.t) run.out = spans[i].out;
            ++i;
        }
        const Bound* hit = run.in.t > tmin ? &run.in : run.out.t > tmin ? &run.out : nullptr;
        if (!hit) continue;
        if (!(hit->t < tmax)) return false;
        h.t = hit->t;
        h.normal = hit->normal;
        return true;
    }
    return false;
}

bool inside(const SphereSweepShape& s, const glm::dvec3& p) {
    if (!s.valid || !s.box.contains(p)) return false;
    for (const SweepSegment& seg : s.segments) {
        if (!seg.box.contains(p)) continue;
        // min over s of |p - c(s)|^2 - r(s)^2: at an end or where its derivative vanishes.
        const int n = seg.degree;
        glm::dvec3 wc[4];
        for (int i = 0; i <= n; ++i) wc[i] = i == 0 ? p - seg.c[0] : -seg.c[i];
        const Poly w[3] = {poly_of(wc, n, 0), poly_of(wc, n, 1), poly_of(wc, n, 2)};
        const Poly rr = poly_of(seg.r, n);
        const Poly f = add(dot(w, w), -1, rr * rr), df = derivative(f);
        double cand[Poly::kMax + 2] = {0, 1};
        const int m = 2 + root_candidates(df, 0, 1, cand + 2, Poly::kMax);
        for (int i = 0; i < m; ++i)
            if (eval_poly(f.c, f.n, cand[i]) < 0) return true;
    }
    return false;
}

}  // namespace lumen::render
