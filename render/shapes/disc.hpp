// Disc: a flat ring (outer radius, optional hole). Its inside, as POV-Ray's, is the whole
// half-space behind it (opposite the normal), whatever the radius; CSG still bounds it by the
// disc's own box, as POV-Ray bounds it by its bounding box. That box is not the tightest: it
// is POV-Ray's (see bounds()), which decides what an intersection with a disc shows.
#pragma once
#include "render/shapes/shape.hpp"

namespace lumen::render {

// POV-Ray's disc box is kDiscBoxThickness deep on each side of the disc, in the disc's own
// units (it scales with the object).
inline constexpr double kDiscBoxThickness = 1e-3;

struct DiscShape {
    glm::dvec3 centre{0}, normal{0, 1, 0};
    double radius2 = 1, hole2 = 0;
    bool valid = true;
    double thickness = kDiscBoxThickness;  // the box's half-depth along the normal
};
DiscShape make_disc(const scene::Disc& d);
bool intersect(const DiscShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
inline bool inside(const DiscShape& s, const glm::dvec3& p) {
    return s.valid && glm::dot(p - s.centre, s.normal) < 0;
}
Aabb bounds(const DiscShape& s);
inline Aabb solid_bounds(const DiscShape&) { return Aabb::everything(); }

template <> struct ShapeTraits<scene::Disc> : PreparedBy<scene::Disc, DiscShape, make_disc> {
    static bool bake(const scene::Disc& d, const scene::Transform& xf, DiscShape& out);
};

}  // namespace lumen::render
