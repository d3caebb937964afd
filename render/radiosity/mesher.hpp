// Meshing scene primitives into radiosity patches in world space (object transforms applied).
// Covered: box, plane (clipped to given bounds), triangle, polygon, mesh, sphere, disc,
// cylinder, cone, torus. CSG and the unsupported shapes give no patches (they can still
// occlude through the tracer once integrated).
#pragma once
#include <array>
#include <vector>

#include <glm/vec3.hpp>

#include "render/radiosity/patch.hpp"
#include "scene/object.hpp"

namespace lumen::render::radiosity {

struct MeshOptions {
    double max_edge = 1.0;  // target edge length of the elements (world units)
    // Infinite planes are clipped to this box (e.g. the scene bounds plus a margin).
    glm::dvec3 bounds_min{-100}, bounds_max{100};
    bool inward = false;  // flip every patch (meshing the inside of an enclosure)
    int min_segments = 8; // around curved surfaces, whatever max_edge says
};

// The material of the patches; the caller maps the object's texture to it.
struct SurfaceProps {
    glm::dvec3 rho{0};
    glm::dvec3 emission{0};
    int object = -1;
};

// True when mesh_object produces patches for this shape.
bool meshable(const scene::Object& object);

// The object's surface placed by `to_world`, as patches whose edges are at most about
// max_edge long, front sides facing out of the solid (or in, with options.inward). Degenerate
// pieces are dropped.
std::vector<Patch> mesh_object(const scene::Object& object, const scene::Transform& to_world,
                               const MeshOptions& options, const SurfaceProps& props);
// The same, placed by the object's own transform.
inline std::vector<Patch> mesh_object(const scene::Object& object, const MeshOptions& options,
                                      const SurfaceProps& props) {
    return mesh_object(object, object.transform, options, props);
}

// Splits a simple (possibly non-convex) planar polygon into triangles by ear clipping.
// Returns vertex index triples into `loop`.
std::vector<std::array<size_t, 3>> triangulate(const std::vector<glm::dvec3>& loop);

}  // namespace lumen::render::radiosity
