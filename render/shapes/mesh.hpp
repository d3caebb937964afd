// mesh / mesh2: triangles in a per-mesh BVH, held by pointer (the BVH is large).
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "render/bvh.hpp"
#include "render/wide_bvh.hpp"
#include "render/shapes/triangle.hpp"

namespace lumen::render {

struct MeshShape {
    const scene::Mesh* mesh = nullptr;
    std::vector<TriangleCore> tris;    // in BVH order
    std::vector<uint32_t> face;        // source face of each entry of tris
    WideBvh bvh;                       // empty when built without acceleration
    Aabb box;
    bool valid = true;
};
// `accelerate` = false skips the BVH (a one-off inside test); queries then scan every face.
std::unique_ptr<MeshShape> make_mesh(const scene::Mesh& m, bool accelerate = true);
bool intersect(const MeshShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
// Some triangle (not necessarily the nearest) at tmin < t < tmax, its t in `t`: a shadow
// ray's test, which may stop at the first one.
bool any_hit(const MeshShape& s, const LocalRay& r, double tmin, double tmax, double& t);
bool inside(const MeshShape& s, const glm::dvec3& p);
Aabb bounds(const MeshShape& s);

// Only a mesh with an inside_vector has an inside.
inline Aabb solid_bounds(const MeshShape& s) { return s.mesh->inside_vector ? bounds(s) : Aabb{}; }

// The prepared form is the pointer (shape.hpp forwards to the mesh).
using MeshPtr = std::unique_ptr<MeshShape>;

template <> struct ShapeTraits<scene::Mesh> {
    using Prepared = MeshPtr;
    static constexpr double min_depth = kDepthDefault;
    static Prepared prepare(const scene::Mesh& m, bool accelerate) {
        return make_mesh(m, accelerate);
    }
    // Not baked: traced in object space under its transform.
    static bool bake(const scene::Mesh&, const scene::Transform&, Prepared&) { return false; }
};

}  // namespace lumen::render
