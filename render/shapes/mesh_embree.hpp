// A mesh's triangles traversed by Embree 3 (libembree-dev), where lumen is built with it: its
// single-precision BVH finds the triangle a ray meets several times faster than lumen's own,
// and the triangle's plane, kept in double precision, gives the distance reported. Which
// triangle is met may differ from lumen's own BVH only for rays within single-precision
// rounding of an edge (mesh_embree.cpp).
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "base/huge_pages.hpp"
#include "render/shapes/triangle.hpp"

namespace lumen::render {

class EmbreeMesh {
public:
    // Built over triangles `tris`, triangle i's corners being vertices[index[3 i + k]]; null
    // where Embree is not built in, cannot be started, or a vertex does not fit in single
    // precision. The triangles are not needed afterwards.
    static std::unique_ptr<EmbreeMesh> build(const std::vector<glm::dvec3>& vertices,
                                             const std::vector<uint32_t>& index,
                                             const std::vector<TriangleCore>& tris);
    static bool built_in();
    ~EmbreeMesh();
    EmbreeMesh(const EmbreeMesh&) = delete;
    EmbreeMesh& operator=(const EmbreeMesh&) = delete;

    // The triangle met (its index in `tris`), the distance, the weights of its corners 1 and
    // 2 (single precision: they only blend normals and uvs) and its plane's normal, e1 x e2.
    struct Found {
        uint32_t tri = 0;
        double t = 0, u = 0, v = 0;
        glm::dvec3 normal{0};
    };
    // The nearest triangle hit at tmin < t < tmax.
    bool nearest(const LocalRay& r, double tmin, double tmax, Found& out) const;
    // Some triangle hit at tmin < t < tmax (a shadow ray's test).
    bool any(const LocalRay& r, double tmin, double tmax, Found& out) const;
    // The number of triangles crossed at 0 < t (inside tests: the parity of the crossings).
    int crossings(const LocalRay& r) const;

    // A triangle's plane: points p with dot(n, p) = d. Half a cache line, where the triangle
    // takes more than one: a scattered ray's hit waits on one load.
    struct Plane {
        glm::dvec3 n;
        double d;
    };

private:
    EmbreeMesh() = default;
    std::vector<Plane, HugePages<Plane>> planes_;
    glm::dvec3 centre_{0};   // of the mesh's box: Embree's coordinates are relative to it
    void* scene_ = nullptr;  // RTCScene
};

}  // namespace lumen::render
