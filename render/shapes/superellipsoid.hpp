// superellipsoid { <e, n> }: (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1 in [-1, 1]^3, found
// as POV-Ray finds it: the ray cut at the box and at the nine planes through the axes and
// diagonals, each piece searched for a sign change (or a grazing approach).
#pragma once
#include <limits>
#include "render/shapes/shape.hpp"

namespace lumen::render {

struct SuperellipsoidShape {
    glm::dvec3 power{2, 1, 2};  // POV-Ray's (2/e, e/n, 2/n); n = 0 gives infinities, kept
    bool valid = true;
};

SuperellipsoidShape make_superellipsoid(const scene::Superellipsoid& s);
bool intersect(const SuperellipsoidShape& s, const LocalRay& r, double tmin, double tmax,
               ShapeHit& h);
bool inside(const SuperellipsoidShape& s, const glm::dvec3& p);
Aabb bounds(const SuperellipsoidShape& s);
inline Aabb solid_bounds(const SuperellipsoidShape& s) { return bounds(s); }

// The distance-like function: < 0 inside, 0 on the surface.
double superellipsoid_value(const SuperellipsoidShape& s, const glm::dvec3& p);
// Every hit POV-Ray reports along o + k d (d unit), as object-space distances k, in the order
// found (ascending but for rounding); returns the count. With `nearest_beyond` (a k), the
// search may stop once the nearest hit beyond it is known: at the first piece that starts
// past a hit found there (by more than rounding), since later pieces hold only later hits.
constexpr int kMaxSuperellipsoidHits = 22;  // two per piece of the ray at most
int superellipsoid_hits(const SuperellipsoidShape& s, const glm::dvec3& o, const glm::dvec3& d,
                        double len, double* ks,
                        double nearest_beyond = std::numeric_limits<double>::quiet_NaN());

inline constexpr double kDepthSuperellipsoid = 1e-4;

template <>
struct ShapeTraits<scene::Superellipsoid>
    : PreparedBy<scene::Superellipsoid, SuperellipsoidShape, make_superellipsoid,
                 &kDepthSuperellipsoid> {
    // Not baked: traced in its own space, where the cutting planes are.
    static bool bake(const scene::Superellipsoid&, const scene::Transform&, SuperellipsoidShape&) {
        return false;
    }
};

}  // namespace lumen::render
