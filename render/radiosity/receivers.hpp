// The receiving side of the solution: the patches of the scene
// mesh shoot (their B is the solve's), and finer elements receive. The final gather runs at
// the vertices the camera sees; elements whose gathered G differs between corners by more
// than a tolerance split in four (edge midpoints), down to a minimum size and within a vertex
// budget, and the new vertices gather from the unchanged B. Splits leave T-junctions
// (a split element beside an unsplit one): the unsplit side is shown as if split too, its
// missing midpoints interpolated from their edges, so the preview has no cracks.
#pragma once
#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <glm/vec3.hpp>

#include "render/intersector.hpp"
#include "render/radiosity/options.hpp"
#include "render/radiosity/scene_mesh.hpp"
#include "render/radiosity/scene_solution.hpp"
#include "scene/scene.hpp"

namespace lumen::render::radiosity {

class ReceiverMesh {
public:
    // A triangle of vertex indices (scene mesh vertices first, then midpoints).
    struct Triangle {
        std::array<uint32_t, 3> v{};
        uint8_t sides = 0;  // bit s: side s is gathered (seen by the camera)
        uint8_t depth = 0;  // splits above it
    };

    explicit ReceiverMesh(const SceneMesh& mesh);

    // The midpoint of edge (a, b), created (on the first call, offset into the triangle
    // whose third corner is `c` for its gathers) when it does not exist yet.
    uint32_t midpoint(uint32_t a, uint32_t b, uint32_t c);
    size_t vertex_count() const { return positions_.size(); }
    size_t added_vertices() const { return positions_.size() - mesh_.vertices.size(); }
    const glm::dvec3& position(uint32_t v) const { return positions_[v]; }

    // G at barycentric `bary` of scene mesh element `element` on `side`: descends through
    // the splits (real, or implied by a neighbour's midpoints) to a leaf and interpolates.
    glm::dvec3 value(long element, const glm::dvec3& bary, uint32_t side) const;
    // Whether value() knows `side` of scene mesh element `element`: its corners' G is known
    // (then so is every midpoint gathered below them).
    bool covers(long element, uint32_t side) const;

    std::vector<glm::dvec3> G;         // per vertex side (2 v + side)
    // Per vertex side: G holds its incident light (gathered, or the solution's fallback);
    // without a fallback the others hold only a placeholder.
    std::vector<char> known;
    std::vector<Triangle> leaves;      // the elements after splitting
    size_t split = 0;                  // elements split

    // Where the gathers of vertex v start and its front (side 0) normal.
    const glm::dvec3& origin(uint32_t v) const { return origins_[v]; }
    const glm::dvec3& normal(uint32_t v) const { return normals_[v]; }
    // The primitive vertex v lies on, and how far its point may be off that primitive's true
    // surface (a midpoint of a curved shape's chord lies inside it).
    const scene::Object* object(uint32_t v) const { return objects_[v]; }
    double reach(uint32_t v) const { return reach_[v]; }

private:
    const SceneMesh& mesh_;
    std::vector<glm::dvec3> positions_, normals_, origins_;  // origins_: where gathers start
    std::vector<const scene::Object*> objects_;
    std::vector<double> reach_;
    std::unordered_map<uint64_t, uint32_t> midpoints_;       // edge (lo, hi) -> vertex
};

// The final gather at the `wanted` vertex sides with `rays` rays each against the solution's
// B and `unmeshed` (the others keep `fallback`, or are not known where it is empty), the
// adaptive subdivision, and one pass of neighbour smoothing over the resulting triangles (it
// cuts the per-vertex ray noise); splits, smoothing and buried sides use known values only.
ReceiverMesh receive(const scene::Scene& scene, const SceneMesh& mesh,
                     const Intersector& geometry, const std::vector<glm::dvec3>& B,
                     const std::vector<char>& wanted, int rays, int threads,
                     const std::vector<glm::dvec3>& fallback,
                     const SubdivisionOptions& options,
                     const SurfaceRadiance* unmeshed = nullptr);

// Buried vertex sides (gathers that started inside solid matter: a floor vertex under a box
// standing on it, a ring sunk into a column) take the mean of their unburied neighbours on
// the same side over the triangles sharing them, up to three rings deep; those with none
// near keep what they gathered. Filled ones are no longer buried.
// `known` (per vertex side, null: all) says which neighbours have a value to give.
void fill_buried(const std::vector<ReceiverMesh::Triangle>& triangles, std::vector<glm::dvec3>& G,
                 std::vector<char>& buried, const std::vector<char>* known = nullptr);

// One pass of neighbour averaging over the vertices sharing a triangle (same side), from the
// neighbours whose value is `known` (null: all).
std::vector<glm::dvec3> smooth(const std::vector<ReceiverMesh::Triangle>& triangles,
                               const std::vector<glm::dvec3>& G,
                               const std::vector<char>* known = nullptr);

}  // namespace lumen::render::radiosity
