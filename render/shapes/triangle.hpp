// Triangle and smooth_triangle: two-sided, no inside. TriangleCore is also the unit of a
// mesh's BVH.
#pragma once
#include <array>

#include "render/shapes/shape.hpp"

namespace lumen::render {

// The part of a triangle the Moller-Trumbore test needs.
struct TriangleCore { glm::dvec3 p0{0}, e1{0}, e2{0}; };
// How far outside its edges (in barycentric weight) a hit still counts: a ray through an edge
// two triangles share must hit one of them, and rounding may put it a hair outside both
// (camera/mesh_camera's rays through the vases' axes found cracks along every meridian).
inline constexpr double kEdgeSlack = 1e-9;
// Barycentric hit: t in (tmin, tmax), u and v the weights of vertices 1 and 2. `slack` 0 for
// crossing counts (inside()), where slack would count more edges twice.
bool hit_triangle(const TriangleCore& s, const LocalRay& r, double tmin, double tmax, double& t,
                  double& u, double& v, double slack = kEdgeSlack);
// Null (zero-area or non-finite) triangles are skipped.
bool make_triangle_core(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                        TriangleCore& out);
// Barycentric blend of vertex normals; the flat normal where the blend vanishes.
glm::dvec3 blend_normals(const std::array<glm::dvec3, 3>& n, const glm::dvec3& flat, double u,
                         double v);

struct TriangleShape {
    TriangleCore core;
    glm::dvec3 normal{0, 1, 0};     // geometric: e1 x e2
    std::array<glm::dvec3, 3> n{};  // vertex normals when smooth
    bool smooth = false, valid = true;
};
TriangleShape make_triangle(const scene::Triangle& t);
bool intersect(const TriangleShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
inline bool inside(const TriangleShape&, const glm::dvec3&) { return false; }  // no inside
Aabb bounds(const TriangleShape& s);
inline Aabb solid_bounds(const TriangleShape&) { return {}; }

template <>
struct ShapeTraits<scene::Triangle> : PreparedBy<scene::Triangle, TriangleShape, make_triangle> {
    static bool bake(const scene::Triangle& t, const scene::Transform& xf, TriangleShape& out);
};

}  // namespace lumen::render
