// Primitive shapes prepared for intersection, in object space. Each family lives in its own
// render/shape_*.cpp. A shape is hit by an object-space ray (origin o, direction d, d NOT unit
// length: it is the world unit direction through the inverse transform), so the parameter t
// is the same as the world distance. Degenerate input gives a shape that is never hit.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "render/bounds.hpp"
#include "render/bvh.hpp"
#include "scene/object.hpp"

namespace lumen::render {

struct LocalRay {
    glm::dvec3 o, d;
    glm::dvec3 at(double t) const { return o + t * d; }
};

// What a shape reports; the normal is in object space, outward, not necessarily unit length.
struct ShapeHit {
    double t = 0;
    glm::dvec3 normal{0, 1, 0};
    glm::dvec2 uv{0};
    const scene::LayeredTexture* texture = nullptr;  // per-face mesh texture, if any
};

// Minimum depths of POV-Ray's objects (povray-semantics.md §7.3).
constexpr double kDepthDefault = 1e-6;  // sphere, plane, box, disc, triangle, mesh, ...
constexpr double kDepthTorus = 1e-4;
constexpr double kDepthPolygon = 1e-8;

struct SphereShape { glm::dvec3 centre{0}; double radius = 1, radius2 = 1; bool valid = true; };
SphereShape make_sphere(const scene::Sphere& s);
bool intersect(const SphereShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
bool inside(const SphereShape& s, const glm::dvec3& p);
Aabb bounds(const SphereShape& s);

struct PlaneShape { glm::dvec3 normal{0, 1, 0}; double distance = 0; bool valid = true; };
PlaneShape make_plane(const scene::Plane& p);
bool intersect(const PlaneShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
bool inside(const PlaneShape& s, const glm::dvec3& p);
Aabb bounds(const PlaneShape& s);

struct BoxShape { Aabb box; bool valid = true; };
BoxShape make_box(const scene::Box& b);
bool intersect(const BoxShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
bool inside(const BoxShape& s, const glm::dvec3& p);
Aabb bounds(const BoxShape& s);

// Cylinder and cone share one canonical frame: axis along local z from 0 to `length`,
// radius r0 at z = 0 and r1 at z = length (equal for a cylinder).
struct ConeShape {
    glm::dmat3 to_axis{1.0};  // rotation taking object space (minus base) to the axis frame
    glm::dvec3 base{0};
    double length = 1, r0 = 1, r1 = 1;
    bool open = false, valid = true;
};
ConeShape make_cylinder(const scene::Cylinder& c);
ConeShape make_cone(const scene::Cone& c);
bool intersect(const ConeShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
bool inside(const ConeShape& s, const glm::dvec3& p);
Aabb bounds(const ConeShape& s);

struct TorusShape { double major = 1, minor = 0.25; bool valid = true; };
TorusShape make_torus(const scene::Torus& t);
bool intersect(const TorusShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
bool inside(const TorusShape& s, const glm::dvec3& p);
Aabb bounds(const TorusShape& s);

struct DiscShape {
    glm::dvec3 centre{0}, normal{0, 1, 0};
    double radius2 = 1, hole2 = 0;
    bool valid = true;
};
DiscShape make_disc(const scene::Disc& d);
bool intersect(const DiscShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
Aabb bounds(const DiscShape& s);

// The part of a triangle the Moller-Trumbore test needs (also the unit of a mesh's BVH).
struct TriangleCore { glm::dvec3 p0{0}, e1{0}, e2{0}; };
// Barycentric hit: t in (tmin, tmax), u and v the weights of vertices 1 and 2.
bool hit_triangle(const TriangleCore& s, const LocalRay& r, double tmin, double tmax, double& t,
                  double& u, double& v);
// Null (zero-area or non-finite) triangles are skipped.
bool make_triangle_core(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                        TriangleCore& out);

struct TriangleShape {
    TriangleCore core;
    glm::dvec3 normal{0, 1, 0};     // geometric: e1 x e2
    std::array<glm::dvec3, 3> n{};  // vertex normals when smooth
    bool smooth = false, valid = true;
};
TriangleShape make_triangle(const scene::Triangle& t);
bool intersect(const TriangleShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
Aabb bounds(const TriangleShape& s);
// Barycentric blend of vertex normals; the flat normal where the blend vanishes.
glm::dvec3 blend_normals(const std::array<glm::dvec3, 3>& n, const glm::dvec3& flat, double u,
                         double v);

struct PolygonShape {
    glm::dvec3 normal{0, 1, 0};
    double distance = 0;
    int axis_u = 0, axis_v = 2;                 // the dominant-axis projection plane
    std::vector<glm::dvec2> edges;              // pairs of projected end points
    Aabb box;
    bool valid = true;
};
PolygonShape make_polygon(const scene::Polygon& p);
bool intersect(const PolygonShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
Aabb bounds(const PolygonShape& s);

struct MeshShape {
    const scene::Mesh* mesh = nullptr;
    std::vector<TriangleCore> tris;    // in BVH order
    std::vector<uint32_t> face;        // source face of each entry of tris
    Bvh bvh;                           // empty when built without acceleration
    Aabb box;
    bool valid = true;
};
// `accelerate` = false skips the BVH (a one-off inside test); queries then scan every face.
std::unique_ptr<MeshShape> make_mesh(const scene::Mesh& m, bool accelerate = true);
bool intersect(const MeshShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
bool inside(const MeshShape& s, const glm::dvec3& p);
Aabb bounds(const MeshShape& s);

}  // namespace lumen::render
