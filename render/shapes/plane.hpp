// Plane n̂·p = d and the half-space n̂·p < d inside it.
#pragma once
#include "render/shapes/shape.hpp"

namespace lumen::render {

struct PlaneShape { glm::dvec3 normal{0, 1, 0}; double distance = 0; bool valid = true; };
PlaneShape make_plane(const scene::Plane& p);
bool intersect(const PlaneShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
bool inside(const PlaneShape& s, const glm::dvec3& p);
Aabb bounds(const PlaneShape& s);
// The half-space's box: bounded on one side where the normal lies along an axis, else infinite.
Aabb solid_bounds(const PlaneShape& s);
// The same for the plane inverted: the other half-space (a difference's `plane { y, 0 }`).
Aabb complement_solid_bounds(const PlaneShape& s);

template <> struct ShapeTraits<scene::Plane> : PreparedBy<scene::Plane, PlaneShape, make_plane> {
    static bool bake(const scene::Plane& p, const scene::Transform& xf, PlaneShape& out);
};

}  // namespace lumen::render
