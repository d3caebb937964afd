// Axis-aligned bounding boxes and the ray-box slab test shared by shapes, CSG and the BVH.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/vec3.hpp>

#include "scene/transform.hpp"

namespace lumen::render {

struct Aabb {
    static constexpr double inf = std::numeric_limits<double>::infinity();
    glm::dvec3 lo{inf}, hi{-inf};  // default: empty

    static Aabb everything() { return {glm::dvec3(-inf), glm::dvec3(inf)}; }
    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    // Finite boxes can go into a BVH; infinite ones are tested on every ray.
    bool finite() const {
        return std::isfinite(lo.x) && std::isfinite(lo.y) && std::isfinite(lo.z) &&
               std::isfinite(hi.x) && std::isfinite(hi.y) && std::isfinite(hi.z);
    }
    void expand(const glm::dvec3& p) { lo = glm::min(lo, p); hi = glm::max(hi, p); }
    void expand(const Aabb& b) { lo = glm::min(lo, b.lo); hi = glm::max(hi, b.hi); }
    glm::dvec3 centre() const { return 0.5 * (lo + hi); }
    double surface_area() const {
        if (empty()) return 0;
        glm::dvec3 e = hi - lo;
        return 2 * (e.x * e.y + e.y * e.z + e.z * e.x);
    }
    bool contains(const glm::dvec3& p) const {
        return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z &&
               p.z <= hi.z;
    }
};

inline Aabb intersect(const Aabb& a, const Aabb& b) {
    return {glm::max(a.lo, b.lo), glm::min(a.hi, b.hi)};
}

// World box of an object-space box: the 8 transformed corners (infinite stays infinite).
inline Aabb transformed(const Aabb& b, const scene::Transform& xf) {
    if (b.empty()) return b;
    if (!b.finite()) return Aabb::everything();
    Aabb out;
    for (int i = 0; i < 8; ++i) {
        glm::dvec3 c{(i & 1) ? b.hi.x : b.lo.x, (i & 2) ? b.hi.y : b.lo.y,
                     (i & 4) ? b.hi.z : b.lo.z};
        out.expand(xf.point(c));
    }
    return out;
}

// A ray prepared for many slab tests. Zero direction components get a huge finite inverse
// instead of infinity, so an origin lying exactly on a slab plane gives 0, never 0*inf = NaN.
struct SlabRay {
    glm::dvec3 origin, inv_dir;
    SlabRay(const glm::dvec3& o, const glm::dvec3& d) : origin(o) {
        for (int i = 0; i < 3; ++i)
            inv_dir[i] = d[i] != 0 ? 1.0 / d[i] : std::copysign(1e300, d[i]);
    }
    // Entry/exit of the box clipped to [t0, t1]; false when the ray misses it there.
    bool hits(const Aabb& b, double t0, double t1, double& enter, double& exit) const {
        for (int i = 0; i < 3; ++i) {
            double a = (b.lo[i] - origin[i]) * inv_dir[i];
            double c = (b.hi[i] - origin[i]) * inv_dir[i];
            double near = a < c ? a : c, far = a < c ? c : a;
            t0 = near > t0 ? near : t0;  // written so a NaN never wins
            t1 = far < t1 ? far : t1;
        }
        enter = t0;
        exit = t1;
        return t0 <= t1;
    }
    bool hits(const Aabb& b, double t0, double t1) const {
        double e, x;
        return hits(b, t0, t1, e, x);
    }
};

}  // namespace lumen::render
