#include "render/shapes/parametric.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>

#include "render/function_host.hpp"
#include "render/shapes/container.hpp"

namespace lumen::render {

namespace {

constexpr int kMaxStack = 32;  // POV-Ray's depth of pieces waiting

struct Piece {
    double u0, u1, v0, v1;
    uint64_t number;  // 1 the whole rectangle; 2n and 2n + 1 the halves of n
};

// The halves of a piece, the longer side split (v when it is strictly longer).
void split(const Piece& p, Piece& low, Piece& high) {
    low = high = p;
    low.number = 2 * p.number;
    high.number = 2 * p.number + 1;
    if (p.v1 - p.v0 > p.u1 - p.u0) {
        low.v1 = high.v0 = (p.v0 + p.v1) / 2;
    } else {
        low.u1 = high.u0 = (p.u0 + p.u1) / 2;
    }
}

double coordinate(const ParametricShape& s, int axis, double u, double v) {
    const double a[3] = {u, v, 0};
    return fn::evaluate(*s.p.functions[axis], a, s.context);
}

// [min(a, b) - e, max(a, b) + e], widened so that a slope of G over d fits between a and b.
glm::dvec2 interval(double G, double d, double a, double b) {
    const double e = std::max(0.0, (G * d - std::fabs(a - b)) / 2);
    return {std::min(a, b) - e, std::max(a, b) + e};
}

// POV-Ray's bounds of one coordinate over a piece from its four corners, each less the
// accuracy (POV-Ray subtracts it), widened by max_gradient along v, then along u.
glm::dvec2 corner_bounds(const ParametricShape& s, int axis, const Piece& p) {
    const double A = s.p.accuracy, G = s.p.max_gradient;
    const double du = p.u1 - p.u0, dv = p.v1 - p.v0;
    const double f00 = coordinate(s, axis, p.u0, p.v0) - A, f01 = coordinate(s, axis, p.u0, p.v1) - A;
    const double f10 = coordinate(s, axis, p.u1, p.v0) - A, f11 = coordinate(s, axis, p.u1, p.v1) - A;
    const glm::dvec2 left = interval(G, dv, f00, f01), right = interval(G, dv, f10, f11);
    return {interval(G, du, left.x, right.x).x, interval(G, du, left.y, right.y).y};
}

// The table's entry for `p` and below: the corner bounds at the last level, the union of the
// halves above it.
glm::dvec2 fill(const ParametricShape& s, int axis, const Piece& p, uint64_t leaves,
                std::vector<glm::dvec2>& table) {
    glm::dvec2 b;
    if (p.number >= leaves) {
        b = corner_bounds(s, axis, p);
    } else {
        Piece low, high;
        split(p, low, high);
        const glm::dvec2 l = fill(s, axis, low, leaves, table), h = fill(s, axis, high, leaves, table);
        b = {std::min(l.x, h.x), std::max(l.y, h.y)};
    }
    table[p.number] = b;
    return b;
}

glm::dvec3 point(const ParametricShape& s, double u, double v) {
    return {coordinate(s, 0, u, v), coordinate(s, 1, u, v), coordinate(s, 2, u, v)};
}

}  // namespace

ParametricShape make_parametric(const scene::Parametric& p) {
    ParametricShape out;
    out.p = p;
    if (p.globals) out.context.noise_generator = p.globals->noise_generator;
    out.context.host = &function_host();
    out.valid = std::all_of(p.functions.begin(), p.functions.end(),
                            [](const fn::ProgramPtr& f) { return f && f->params >= 2 && f->params <= 3; }) &&
                !p.container.empty();
    if (!out.valid || p.precompute_depth < 1) return out;
    const uint64_t size = uint64_t(1) << p.precompute_depth;
    const Piece whole{p.uv_lo.x, p.uv_hi.x, p.uv_lo.y, p.uv_hi.y, 1};
    for (int axis = 0; axis < 3; ++axis) {
        if (!p.precompute[axis]) continue;
        auto table = std::make_shared<std::vector<glm::dvec2>>(size);
        fill(out, axis, whole, size / 2, *table);
        out.tables[axis] = std::move(table);
    }
    return out;
}

bool intersect(const ParametricShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h) {
    if (!s.valid) return false;
    const double len = glm::length(r.d);
    if (!(len > 0)) return false;
    double t1, t2;
    glm::dvec3 n1, n2;
    if (!container_span(s.p.container, r, len, t1, t2, n1, n2)) return false;
    const double A = s.p.accuracy;
    if (t1 == t2) t1 = 0;
    t1 += 4 * A;
    if (t1 > t2) return false;
    const uint64_t table_size = s.p.precompute_depth ? uint64_t(1) << s.p.precompute_depth : 0;

    Piece stack[kMaxStack];
    int top = 0;
    stack[top++] = {s.p.uv_lo.x, s.p.uv_hi.x, s.p.uv_lo.y, s.p.uv_hi.y, 1};
    double best = Aabb::inf;
    glm::dvec2 best_uv{0};
    while (top > 0) {
        const Piece p = stack[--top];
        double slab_lo[3], slab_hi[3];
        int slabs = 0;
        double t_pot = 0, t_len = 0;
        bool discard = false;
        for (int k = 0; k < 3 && !discard; ++k) {
            const glm::dvec2 b = s.tables[k] && p.number < table_size ? (*s.tables[k])[p.number]
                                                                     : corner_bounds(s, k, p);
            if (std::fabs(r.d[k]) < 1e-10) {
                discard = r.o[k] < b.x || r.o[k] > b.y;
                continue;
            }
            double a = (b.y - r.o[k]) / r.d[k], c = (b.x - r.o[k]) / r.d[k];
            if (a > c) std::swap(a, c);
            if (a > t2 || c < t1 || a > best) {
                discard = true;
                continue;
            }
            for (int j = 0; j < slabs; ++j)
                if (a > slab_hi[j] || c < slab_lo[j]) discard = true;
            slab_lo[slabs] = a;
            slab_hi[slabs++] = c;
            t_pot = a;  // POV-Ray's: the last axis's entry, not the latest entry
            t_len = std::max(t_len, c - a);
        }
        if (discard) continue;
        const double side = std::max(p.u1 - p.u0, p.v1 - p.v0);
        if (std::min(side, t_len) < A || top + 2 > kMaxStack) {
            if (t_pot > t1 && t_pot < best) {
                best = t_pot;
                best_uv = {p.u0, p.v0};
            }
            continue;
        }
        Piece low, high;
        split(p, low, high);
        stack[top++] = high;
        stack[top++] = low;  // the low half first
    }
    if (!(best < t2) || !(best > tmin) || !(best < tmax)) return false;
    h.t = best;
    h.uv = best_uv;
    const glm::dvec3 p0 = point(s, best_uv.x, best_uv.y);
    const glm::dvec3 n = glm::cross(point(s, best_uv.x + A, best_uv.y) - p0,
                                    point(s, best_uv.x, best_uv.y + A) - p0);
    const double nl = glm::length(n);
    h.normal = nl > 0 && std::isfinite(nl) ? n / nl : glm::dvec3(0, 1, 0);
    return true;
}

Aabb bounds(const ParametricShape& s) { return container_bounds(s.p.container); }

}  // namespace lumen::render
