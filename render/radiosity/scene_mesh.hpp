// The scene's diffuse surfaces as a welded triangle mesh for the radiosity solution: elements
// know the primitive they came from (so a tracer hit finds its element) and share vertices
// with their coplanar neighbours (so values interpolate across element edges). Every
// surface is two-sided, as in POV: the unknowns are vertex sides (vertex v, side 0 along its
// normal, side 1 against it).
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <glm/vec3.hpp>

#include "render/bvh.hpp"
#include "render/geometry.hpp"
#include "scene/scene.hpp"

namespace lumen::render::radiosity {

struct MeshVertex {
    glm::dvec3 position{0};
    glm::dvec3 normal{0, 0, 1};  // the front (side 0) normal
    glm::dvec3 inward{0};        // towards the inside of the adjacent elements (unit or 0)
    glm::dvec3 rho{0};           // diffuse × pigment at the vertex
    glm::dvec3 emission{0};      // emission × pigment
    double brilliance = 1;       // the finish's: direct light goes with cos^brilliance
    double area = 0;             // a third of the adjacent elements' area
    uint8_t sealed = 0;          // bit s: side s faces into an opaque solid (build_scene_mesh)
};

struct MeshElement {
    std::array<uint32_t, 3> v{};  // vertex indices, counter-clockwise about the normal
    glm::dvec3 normal{0, 0, 1};
    double area = 0;
    const scene::Object* object = nullptr;  // the primitive (as a tracer Hit names it)
};

// The side of element `el` (0 front) that a viewer in direction `towards` sees at a surface
// point of geometric normal `surface_normal`: judged by the true surface, not the element's
// plane, since near a curved shape's silhouette its chord can face away from a viewer whom
// the surface faces.
inline uint32_t seen_side(const MeshElement& el, const glm::dvec3& surface_normal,
                          const glm::dvec3& towards) {
    const bool viewer_above = glm::dot(towards, surface_normal) > 0;
    const bool front_above = glm::dot(el.normal, surface_normal) > 0;
    return viewer_above == front_above ? 0 : 1;
}

struct SceneMesh {
    std::vector<MeshVertex> vertices;
    std::vector<MeshElement> elements;
    Bvh bvh;                      // over elements, in Bvh::order()
    std::vector<Aabb> boxes;      // element boxes
    // The elements of each primitive with their own BVH: a tracer hit names its primitive,
    // so finding its element searches only those (the hot path of every gather ray).
    struct ObjectElements {
        std::vector<uint32_t> elements;
        Bvh bvh;  // over `elements`
    };
    std::vector<ObjectElements> per_object;
    std::unordered_map<const scene::Object*, uint32_t> object_slot;
    // A uniform grid (cells of about one patch) listing the elements whose box meets each
    // cell: a hit point finds its element in O(1) (CSR: cell c holds cell_items[cell_start[c]
    // .. cell_start[c+1]]).
    glm::dvec3 grid_origin{0};
    double grid_cell = 1;
    glm::ivec3 grid_size{0};
    std::vector<uint32_t> cell_start, cell_items;
    std::vector<uint32_t> cell_slots;  // the object slot of each cell item (no element load to skip it)
    // Per element, what projecting a point onto it needs, in one place (its vertices lie
    // elsewhere in memory): corner a, unit normal, edges e1 = b - a and e2 = c - a with their
    // Gram matrix and its inverse determinant.
    struct Frame {
        glm::dvec3 a, normal, e1, e2;
        double d11, d12, d22, inv_det;
    };
    std::vector<Frame> frames;
    Aabb grid_bounds;                  // of every element: hits farther out find none
    double patch_size = 0;        // largest element edge used
    Aabb bounds;                  // of the finite objects
    std::vector<std::string> warnings;  // with source locations
    // Geometry::solid_primitives of the eye (build_scene_mesh with an eye): gather rays that
    // meet one from behind started inside solid matter.
    std::unordered_set<const scene::Object*> solids;

    size_t unknowns() const { return vertices.size() * 2; }

    // The element crossed by the ray near distance t (within `slack`) from `object`, with the
    // barycentric weights of the crossing point; -1 when none.
    long find(const glm::dvec3& origin, const glm::dvec3& dir, double t, double slack,
              const scene::Object* object, glm::dvec3& bary) const;

    // The element of the object in `slot` nearest to surface point p (within `slack` of its
    // plane) whose projection contains p, from the grid cell of p; -1 when none.
    long find_near(const glm::dvec3& p, uint32_t slot, double slack, glm::dvec3& bary) const;
};

// Per-vertex-side `values` (2 v + side) interpolated at barycentric `bary` of element `e`.
inline glm::dvec3 interpolate_sides(const SceneMesh& mesh, const std::vector<glm::dvec3>& values,
                                    long e, const glm::dvec3& bary, uint32_t side) {
    const MeshElement& el = mesh.elements[size_t(e)];
    return bary.x * values[2 * el.v[0] + side] + bary.y * values[2 * el.v[1] + side] +
           bary.z * values[2 * el.v[2] + side];
}

// The default patch size: 1/38 of the scene bounds diagonal (2.5 units in cornell.pov).
double default_patch_size(const Aabb& bounds);

// Meshes every meshable object of the compiled geometry (the tracer's: through unions), infinite
// planes clipped to the bounds. Left out: no_radiosity objects, other CSG and the shapes the
// mesher cannot cut (the gathers evaluate those where their rays land, see point_gather.hpp),
// and pure emitters (diffuse 0 everywhere: a sky sphere's exact colour comes from its
// texture at each ray's hit, and its size does not set the patch size). `ambient_emission`:
// surface_light.hpp.
// With an `eye` (the camera), the vertex sides facing into their own opaque solid object,
// when the eye is outside it, are sealed: nothing can see them, so they get no light.
SceneMesh build_scene_mesh(const Geometry& geometry, double patch_size,
                           const glm::dvec3& ambient_emission = glm::dvec3(0),
                           const glm::dvec3* eye = nullptr);

}  // namespace lumen::render::radiosity
