// text, traced the way POV-Ray traces its TrueType glyphs: the front face (z = 0), the back
// face (z = thickness) and one side wall per outline edge, with POV-Ray's tolerances (a
// glyph quadratic with a discriminant below 1e-10 has no root, so walls are not hit by
// tangent rays) and its even-odd crossing rules for the inside test, which the faces use too.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "render/shapes/text.hpp"

namespace lumen::render {

namespace {

constexpr double kParallel = 1e-10;  // direction components and determinants below: parallel

// B(s) = k2 s^2 + k1 s + k0 of a glyph edge (a line has k2 = 0).
struct Polynomial2 {
    glm::dvec2 k2, k1, k0;
    glm::dvec2 at(double s) const { return (k2 * s + k1) * s + k0; }
    glm::dvec2 tangent(double s) const { return 2.0 * k2 * s + k1; }
};

Polynomial2 polynomial(const GlyphEdge& e) {
    if (!e.curve) return {glm::dvec2(0), e.b - e.a, e.a};
    return {e.a - 2.0 * e.c + e.b, 2.0 * (e.c - e.a), e.a};
}

// The roots in [0, 1] of a s^2 + b s + c as POV-Ray's glyph solver finds them: nearly linear
// below |a| < 1e-20, and none for a discriminant below 1e-10 (tangents).
int glyph_roots(double a, double b, double c, double s[2]) {
    int n = 0;
    auto keep = [&](double x) {
        if (x >= 0 && x <= 1) s[n++] = x;
    };
    if (std::abs(a) < 1e-20) {
        if (std::abs(b) >= 1e-20) keep(-c / b);
        return n;
    }
    const double disc = b * b - 4 * a * c;
    if (disc < 1e-10) return 0;
    const double root = std::sqrt(disc);
    keep((-b + root) / (2 * a));
    keep((-b - root) / (2 * a));
    return n;
}

// Whether the ray toward +x from q crosses a straight edge. An end exactly at q.y counts as
// above; a crossing left of q by less than 1e-10 still counts.
bool crosses_line(const GlyphEdge& e, const glm::dvec2& q) {
    const double x0 = e.a.x, y0 = e.a.y, x1 = e.b.x, y1 = e.b.y;
    if (y0 == y1 || (y0 < q.y) == (y1 < q.y)) return false;
    const bool right0 = x0 > q.x, right1 = x1 > q.x;
    if (right0 != right1) {
        const double m = (y1 - y0) / (x1 - x0);
        const double b = (y1 - q.y) - m * (x1 - q.x);
        return b / m < 1e-10;
    }
    return right0;
}

// A curve root at one of its ends counts only when y passes strictly between the end and
// the control point (so that a crossing at a shared end point is counted once).
bool passes(double y, double end, double control) {
    return !((y <= end && y < control) || (y >= end && y > control));
}

// How many times the ray toward +x from q crosses a quadratic edge.
int crossings_curve(const GlyphEdge& e, const glm::dvec2& q) {
    const double y0 = e.a.y, y1 = e.c.y, y2 = e.b.y;
    if ((y0 < q.y && y1 < q.y && y2 < q.y) || (y0 > q.y && y1 > q.y && y2 > q.y)) return 0;
    const Polynomial2 k = polynomial(e);
    double s[2];
    const int n = glyph_roots(k.k2.y, k.k1.y, k.k0.y - q.y, s);
    int count = 0;
    for (int i = 0; i < n; ++i) {
        if (s[i] <= 1e-10 && !passes(q.y, y0, y1)) continue;
        if (s[i] >= 1 - 1e-10 && !passes(q.y, y1, y2)) continue;
        if (k.at(s[i]).x > q.x) ++count;
    }
    return count;
}

// The contours of a glyph walked as TrueType outlines are: an off-curve point is the control
// point of a quadratic ending at the next point if that is on the curve, else at the midpoint
// with the next control point. The walk starts at the contour's first point as it is and
// closes back to it. Zero-length edges, which cross and hit nothing, are left out.
void walk_contour(const std::vector<scene::Text::Point>& pts, size_t begin, size_t end,
                  std::vector<GlyphEdge>& out) {
    const size_t count = end - begin;
    if (count == 0) return;
    auto point = [&](size_t j) -> const scene::Text::Point& {
        return pts[begin + (j == count ? 0 : j)];
    };
    glm::dvec2 p0 = point(0).p;
    for (size_t j = 1; j <= count; ++j) {
        const scene::Text::Point& pj = point(j);
        GlyphEdge e;
        e.a = p0;
        if (pj.on_curve) {
            e.b = pj.p;
        } else {
            e.curve = true;
            e.c = pj.p;
            if (j == count) e.b = point(0).p;
            else if (point(j + 1).on_curve) e.b = point(j + 1).p;
            else e.b = 0.5 * (pj.p + point(j + 1).p);
        }
        p0 = e.b;
        const bool degenerate = e.curve ? (e.a == e.b && e.a == e.c) : e.a == e.b;
        e.lo = glm::min(e.a, e.b);
        e.hi = glm::max(e.a, e.b);
        if (e.curve) e.lo = glm::min(e.lo, e.c), e.hi = glm::max(e.hi, e.c);
        if (!degenerate) out.push_back(e);
    }
}

// Which side of its edges a contour's material lies on, by majority over its edges: a point a
// hair to the right of each edge's middle is inside or not. TrueType winds outer contours
// clockwise, so the right is usually inside, but fonts are not all well made.
double outward_sign(const PreparedGlyph& g, size_t first, size_t last) {
    const double hair = 1e-6 * (1 + std::max(g.hi.x - g.lo.x, g.hi.y - g.lo.y));
    int votes = 0;
    for (size_t i = first; i < last; ++i) {
        const Polynomial2 k = polynomial(g.edges[i]);
        const glm::dvec2 t = k.tangent(0.5);
        const double len = glm::length(t);
        if (!(len > 0)) continue;
        const glm::dvec2 right = glm::dvec2(t.y, -t.x) / len;
        votes += inside_glyph(g, k.at(0.5) + hair * right) ? -1 : 1;
    }
    return votes < 0 ? -1 : 1;
}

// Entry and exit of the ray through the glyph's box (a little enlarged): the stretch where
// any of its hits can be.
bool box_span(const glm::dvec3& lo, const glm::dvec3& hi, const glm::dvec3& o,
              const glm::dvec3& d, double& enter, double& exit) {
    for (int axis = 0; axis < 3; ++axis) {
        const double pad = 1e-9 * (1 + std::abs(lo[axis]) + std::abs(hi[axis]));
        const double a = lo[axis] - pad, b = hi[axis] + pad;
        if (d[axis] == 0) {
            if (o[axis] < a || o[axis] > b) return false;
            continue;
        }
        double t0 = (a - o[axis]) / d[axis], t1 = (b - o[axis]) / d[axis];
        if (t0 > t1) std::swap(t0, t1);
        enter = std::max(enter, t0);
        exit = std::min(exit, t1);
    }
    return enter <= exit;
}

// The nearest hit of one glyph in (tmin, best), P and D in the glyph's space.
void hit_glyph(const PreparedGlyph& g, double thickness, const glm::dvec3& P,
               const glm::dvec3& D, double tmin, double& best, glm::dvec3& normal) {
    double enter = tmin, exit = best;
    const glm::dvec3 lo(g.lo, std::min(0.0, thickness)), hi(g.hi, std::max(0.0, thickness));
    if (!box_span(lo, hi, P, D, enter, exit)) return;
    if (std::abs(D.z) >= kParallel) {
        const double t0 = -P.z / D.z;
        const double faces[2] = {t0, t0 + thickness / D.z};
        for (int i = 0; i < 2; ++i) {
            const double t = faces[i];
            if (!(t > tmin && t < best)) continue;
            if (!inside_glyph(g, {P.x + t * D.x, P.y + t * D.y})) continue;
            best = t;
            normal = {0, 0, i == 0 ? -1 : 1};
        }
    }
    if (std::abs(D.x) < kParallel && std::abs(D.y) < kParallel) return;
    // The ray's t at a point of its (x, y) path, from the larger usable component.
    auto ray_t = [&](const glm::dvec2& p) {
        return std::abs(D.x) >= kParallel ? (p.x - P.x) / D.x : (p.y - P.y) / D.y;
    };
    auto wall = [&](double t, const glm::dvec2& dir, double outward) {
        if (!(t > tmin && t < best)) return;
        const double z = P.z + t * D.z;
        if (z < 0 || z > thickness) return;
        best = t;
        normal = outward * glm::dvec3(dir.y, -dir.x, 0);
    };
    // Where the ray's (x, y) path runs while it is inside the glyph's box, a little enlarged:
    // an edge whose box it misses has no wall hit (most rays cross a glyph steeply, over
    // few of its edges).
    const glm::dvec2 from(P.x + enter * D.x, P.y + enter * D.y), to(P.x + exit * D.x, P.y + exit * D.y);
    const glm::dvec2 pad(1e-9 * (1 + std::abs(g.lo.x) + std::abs(g.hi.x)),
                         1e-9 * (1 + std::abs(g.lo.y) + std::abs(g.hi.y)));
    const glm::dvec2 path_lo = glm::min(from, to) - pad, path_hi = glm::max(from, to) + pad;
    for (const GlyphEdge& e : g.edges) {
        if (e.hi.x < path_lo.x || e.lo.x > path_hi.x || e.hi.y < path_lo.y || e.lo.y > path_hi.y)
            continue;
        if (!e.curve) {
            const glm::dvec2 d = e.b - e.a;
            const double den = d.y * D.x - d.x * D.y;
            if (std::abs(den) < kParallel) continue;
            const double s = (D.x * (P.y - e.a.y) - D.y * (P.x - e.a.x)) / den;
            if (s < 0 || s > 1) continue;
            wall(ray_t(e.a + s * d), d, e.outward);
            continue;
        }
        // The curve's points on the ray's line D.y x - D.x y + (P.y D.x - P.x D.y) = 0.
        const Polynomial2 k = polynomial(e);
        auto line = [&](const glm::dvec2& v) { return D.y * v.x - D.x * v.y; };
        double s[2];
        const int n = glyph_roots(line(k.k2), line(k.k1), line(k.k0) + P.y * D.x - P.x * D.y, s);
        for (int i = 0; i < n; ++i) {
            glm::dvec2 tangent = k.tangent(s[i]);
            if (tangent == glm::dvec2(0)) tangent = e.b - e.a;  // a cusp: the chord's normal
            wall(ray_t(k.at(s[i])), tangent, e.outward);
        }
    }
}

}  // namespace

bool inside_glyph(const PreparedGlyph& g, const glm::dvec2& q) {
    if (q.y < g.lo.y || q.y > g.hi.y || q.x > g.hi.x) return false;
    int crossings = 0;
    const double left = q.x - 1e-6 * (1 + std::abs(q.x));  // crossings just left of q count
    for (const GlyphEdge& e : g.edges) {
        if (e.lo.y > q.y || e.hi.y < q.y || e.hi.x < left) continue;  // cannot cross
        crossings += e.curve ? crossings_curve(e, q) : int(crosses_line(e, q));
    }
    return crossings % 2 == 1;
}

TextShape make_text(const scene::Text& t) {
    TextShape out;
    out.thickness = t.thickness;
    if (!std::isfinite(t.thickness)) return out;
    for (const scene::Text::Glyph& glyph : t.glyphs) {
        if (glyph.points.empty()) continue;
        PreparedGlyph g;
        g.position = glyph.position;
        g.lo = g.hi = glyph.points.front().p;
        for (const scene::Text::Point& p : glyph.points) {
            g.lo = glm::min(g.lo, p.p);
            g.hi = glm::max(g.hi, p.p);
        }
        std::vector<size_t> contour_edges;  // where each contour's edges start
        size_t begin = 0;
        for (int end : glyph.contour_ends) {
            const size_t stop = std::min<size_t>(std::max(end, 0), glyph.points.size());
            if (stop <= begin) continue;
            contour_edges.push_back(g.edges.size());
            walk_contour(glyph.points, begin, stop, g.edges);
            begin = stop;
        }
        contour_edges.push_back(g.edges.size());
        for (size_t c = 0; c + 1 < contour_edges.size(); ++c) {
            const double sign = outward_sign(g, contour_edges[c], contour_edges[c + 1]);
            for (size_t i = contour_edges[c]; i < contour_edges[c + 1]; ++i)
                g.edges[i].outward = sign;
        }
        if (g.edges.empty()) continue;
        out.box.expand(g.position + glm::dvec3(g.lo, std::min(0.0, t.thickness)));
        out.box.expand(g.position + glm::dvec3(g.hi, std::max(0.0, t.thickness)));
        out.glyphs.push_back(std::move(g));
    }
    std::vector<Aabb> boxes;
    for (const PreparedGlyph& g : out.glyphs) {
        // hit_glyph's own box test pads the glyph's box; this one may be looser.
        Aabb b;
        b.expand(g.position + glm::dvec3(g.lo, std::min(0.0, t.thickness)));
        b.expand(g.position + glm::dvec3(g.hi, std::max(0.0, t.thickness)));
        const glm::dvec3 pad = 1e-6 * (glm::dvec3(1) + glm::abs(b.lo) + glm::abs(b.hi));
        boxes.push_back({b.lo - pad, b.hi + pad});
    }
    out.tree.build(boxes, 2);
    std::vector<PreparedGlyph> ordered;
    for (uint32_t i : out.tree.order()) ordered.push_back(std::move(out.glyphs[i]));
    out.glyphs = std::move(ordered);
    return out;
}

bool intersect(const TextShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h) {
    double best = tmax;
    glm::dvec3 normal{0};
    s.tree.traverse(SlabRay(r.o, r.d), tmin, best, [&](uint32_t i) {
        const PreparedGlyph& g = s.glyphs[i];
        hit_glyph(g, s.thickness, r.o - g.position, r.d, tmin, best, normal);
    });
    if (!(best < tmax)) return false;
    h.t = best;
    h.normal = normal;
    return true;
}

bool inside(const TextShape& s, const glm::dvec3& p) {
    for (const PreparedGlyph& g : s.glyphs) {
        const glm::dvec3 q = p - g.position;
        if (q.z >= 0 && q.z <= s.thickness && inside_glyph(g, {q.x, q.y})) return true;
    }
    return false;
}

Aabb bounds(const TextShape& s) { return s.box; }

}  // namespace lumen::render
