// mesh / mesh2: triangles in a per-mesh BVH (Embree's where lumen is built with it and the
// mesh is big enough to gain from it, else lumen's own), held by pointer (the BVH is large).
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "render/bvh.hpp"
#include "render/wide_bvh.hpp"
#include "render/shapes/mesh_embree.hpp"
#include "render/shapes/triangle.hpp"

namespace lumen::render {

// Shared by the copies of one mesh (ShapeTraits<scene::Mesh>::prepare), as POV-Ray shares a
// mesh's data between copies: `mesh` is a copy, so its bulk lives as long as the shape does.
struct MeshShape {
    scene::Mesh mesh;
    std::vector<TriangleCore> tris;    // in BVH order; none with Embree
    std::vector<uint32_t> face;        // source face of each triangle
    WideBvh bvh;                       // empty when built without acceleration or with Embree
    std::unique_ptr<EmbreeMesh> embree;  // over tris, in their source order
    Aabb box;
    bool valid = true;
};
// How a mesh's queries find their triangles: every face in turn (a one-off inside test),
// lumen's BVH, or Embree's where it is built in (else lumen's).
enum class MeshTraversal { Scan, Bvh, Best };
// Below this many triangles lumen's own BVH serves as well as Embree's.
inline constexpr size_t kEmbreeMinTriangles = 256;
using MeshPtr = std::shared_ptr<const MeshShape>;
// A new prepared mesh.
MeshPtr make_mesh(const scene::Mesh& m, MeshTraversal traversal = MeshTraversal::Best);
// The prepared mesh of m's copies while one is in use (one per traversal), else a new one.
MeshPtr shared_mesh(const scene::Mesh& m, MeshTraversal traversal);
bool intersect(const MeshShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
// Some triangle (not necessarily the nearest) at tmin < t < tmax, its t in `t`: a shadow
// ray's test, which may stop at the first one.
bool any_hit(const MeshShape& s, const LocalRay& r, double tmin, double tmax, double& t);
bool inside(const MeshShape& s, const glm::dvec3& p);
Aabb bounds(const MeshShape& s);

// Only a mesh with an inside_vector has an inside.
inline Aabb solid_bounds(const MeshShape& s) { return s.mesh.inside_vector ? bounds(s) : Aabb{}; }

// The prepared form is the pointer (shape.hpp forwards to the mesh).

template <> struct ShapeTraits<scene::Mesh> {
    using Prepared = MeshPtr;
    static constexpr double min_depth = kDepthDefault;
    static Prepared prepare(const scene::Mesh& m, bool accelerate) {
        return shared_mesh(m, accelerate ? MeshTraversal::Best : MeshTraversal::Scan);
    }
    // Not baked: traced in object space under its transform.
    static bool bake(const scene::Mesh&, const scene::Transform&, Prepared&) { return false; }
};

}  // namespace lumen::render
