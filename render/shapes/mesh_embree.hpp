// A mesh's triangles traversed by Embree 3 (libembree-dev), where lumen is built with it: its
// single-precision BVH finds the triangle a ray meets several times faster than lumen's own,
// and lumen's double-precision test of that triangle gives the distance and weights reported.
// Which triangle is met may differ from lumen's own BVH only for rays within single-precision
// rounding of an edge (mesh_embree.cpp).
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "render/shapes/triangle.hpp"

namespace lumen::render {

class EmbreeMesh {
public:
    // Built over `tris` (which must stay where they are while this lives), triangle i's
    // corners being vertices[index[3 i + k]]; null where Embree is not built in, cannot be
    // started, or a vertex does not fit in single precision.
    static std::unique_ptr<EmbreeMesh> build(const std::vector<glm::dvec3>& vertices,
                                             const std::vector<uint32_t>& index,
                                             const std::vector<TriangleCore>& tris);
    static bool built_in();
    ~EmbreeMesh();
    EmbreeMesh(const EmbreeMesh&) = delete;
    EmbreeMesh& operator=(const EmbreeMesh&) = delete;

    struct Found {
        uint32_t tri = 0;
        double t = 0, u = 0, v = 0;
    };
    // The nearest triangle hit at tmin < t < tmax.
    bool nearest(const LocalRay& r, double tmin, double tmax, Found& out) const;
    // Some triangle hit at tmin < t < tmax (a shadow ray's test).
    bool any(const LocalRay& r, double tmin, double tmax, Found& out) const;
    // The number of triangles crossed at 0 < t (inside tests: the parity of the crossings).
    int crossings(const LocalRay& r) const;

private:
    explicit EmbreeMesh(const std::vector<TriangleCore>& tris) : tris_(tris) {}
    const std::vector<TriangleCore>& tris_;
    glm::dvec3 centre_{0};   // of the mesh's box: Embree's coordinates are relative to it
    void* scene_ = nullptr;  // RTCScene
};

}  // namespace lumen::render
