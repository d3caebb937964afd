// Torus: major radius in the XZ plane around Y, tube radius minor.
#pragma once
#include "render/shapes/shape.hpp"

namespace lumen::render {

struct TorusShape { double major = 1, minor = 0.25; bool valid = true; };
TorusShape make_torus(const scene::Torus& t);
bool intersect(const TorusShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
bool inside(const TorusShape& s, const glm::dvec3& p);
Aabb bounds(const TorusShape& s);
inline Aabb solid_bounds(const TorusShape& s) { return bounds(s); }

template <>
struct ShapeTraits<scene::Torus> : PreparedBy<scene::Torus, TorusShape, make_torus, &kDepthTorus> {
    // Not baked: TorusShape has no centre or axis to carry a transform (traced in object space).
    static bool bake(const scene::Torus&, const scene::Transform&, TorusShape&) { return false; }
};

}  // namespace lumen::render
