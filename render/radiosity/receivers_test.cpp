// Receiving elements: values across a T-junction (a split element beside an unsplit one)
// agree on the shared edge, at any depth of splitting, so the preview has no cracks.
#include <gtest/gtest.h>

#include "render/radiosity/receivers.hpp"

namespace lumen::render::radiosity {
namespace {

// The unit square as two triangles sharing the diagonal (0, 2): e0 = (0, 1, 2), e1 = (0, 2, 3).
SceneMesh square() {
    SceneMesh m;
    m.patch_size = 1;
    for (glm::dvec3 p : {glm::dvec3(0, 0, 0), glm::dvec3(1, 0, 0), glm::dvec3(1, 1, 0),
                         glm::dvec3(0, 1, 0)}) {
        MeshVertex v;
        v.position = p;
        v.rho = glm::dvec3(0.5);
        m.vertices.push_back(v);
    }
    for (std::array<uint32_t, 3> v : {std::array<uint32_t, 3>{0, 1, 2}, {0, 2, 3}}) {
        MeshElement e;
        e.v = v;
        e.area = 0.5;
        m.elements.push_back(e);
    }
    return m;
}

// The value at s along the diagonal from vertex 0 to vertex 2, seen from each element.
glm::dvec3 from_e0(const ReceiverMesh& r, double s) { return r.value(0, {1 - s, 0, s}, 0); }
glm::dvec3 from_e1(const ReceiverMesh& r, double s) { return r.value(1, {1 - s, s, 0}, 0); }

TEST(Receivers, UnsplitMeshInterpolatesLinearly) {
    const SceneMesh m = square();
    ReceiverMesh r(m);
    r.G[2 * 1] = glm::dvec3(1);  // vertex 1, front side
    EXPECT_NEAR(r.value(0, {0.25, 0.5, 0.25}, 0).x, 0.5, 1e-12);
    EXPECT_NEAR(r.value(0, {0.25, 0.5, 0.25}, 1).x, 0.0, 1e-12);  // the back side is its own
    EXPECT_EQ(r.added_vertices(), 0u);
}

TEST(Receivers, TJunctionHasNoCrack) {
    const SceneMesh m = square();
    ReceiverMesh r(m);
    // Split e0 only: its diagonal midpoint hangs on e1's edge.
    const uint32_t ab = r.midpoint(0, 1, 2), bc = r.midpoint(1, 2, 0), ca = r.midpoint(2, 0, 1);
    EXPECT_EQ(r.added_vertices(), 3u);
    EXPECT_EQ(r.midpoint(0, 2, 3), ca);  // the neighbour finds the same vertex
    r.G[2 * ca] = glm::dvec3(1);
    r.G[2 * ab] = glm::dvec3(0.25);
    r.G[2 * bc] = glm::dvec3(0.5);
    // Along the shared edge both sides agree, and peak at the hanging vertex (plain
    // interpolation over e1 would give 0 there: a crack).
    for (double s : {0.0, 0.1, 0.25, 0.4, 0.5, 0.6, 0.9, 1.0})
        EXPECT_NEAR(from_e0(r, s).x, from_e1(r, s).x, 1e-12) << s;
    EXPECT_NEAR(from_e1(r, 0.5).x, 1.0, 1e-12);
    EXPECT_NEAR(from_e1(r, 0.25).x, 0.5, 1e-12);
    // Continuous across the edge too: points a hair off it on either side.
    const double h = 1e-7;
    EXPECT_NEAR(r.value(0, {0.5 - h, 2 * h, 0.5 - h}, 0).x, r.value(1, {0.5 - h, 0.5 - h, 2 * h}, 0).x,
                1e-5);

    // Split e0's corner child (0, ab, ca) once more: the new midpoint on (0, ca) lies on the
    // shared edge two levels below e1, which still follows it.
    const uint32_t deep = r.midpoint(0, ca, ab);
    r.midpoint(0, ab, ca);
    r.midpoint(ab, ca, 0);
    r.G[2 * deep] = glm::dvec3(3);
    for (double s : {0.05, 0.125, 0.2, 0.3, 0.5, 0.75})
        EXPECT_NEAR(from_e0(r, s).x, from_e1(r, s).x, 1e-12) << s;
    EXPECT_NEAR(from_e1(r, 0.25).x, 3.0, 1e-12);
}

TEST(Receivers, BuriedVerticesTakeTheirNeighboursMean) {
    // The square's two triangles share the diagonal (0, 2); vertex 2's front side is buried.
    const std::vector<ReceiverMesh::Triangle> tris{{{0, 1, 2}, 1, 0}, {{0, 2, 3}, 1, 0}};
    std::vector<glm::dvec3> G(8, glm::dvec3(0));
    G[0] = glm::dvec3(1), G[2] = glm::dvec3(2), G[4] = glm::dvec3(-5), G[6] = glm::dvec3(4);
    G[5] = glm::dvec3(7);  // vertex 2's back side, not buried
    std::vector<char> buried(8, 0);
    buried[4] = 1;
    fill_buried(tris, G, buried);
    // Neighbours per triangle: (0, 1) and (0, 3): (1 + 2 + 1 + 4) / 4.
    EXPECT_NEAR(G[4].x, 2.0, 1e-12);
    EXPECT_EQ(buried[4], 0);
    EXPECT_NEAR(G[5].x, 7.0, 1e-12);  // sides are apart
    EXPECT_NEAR(G[0].x, 1.0, 1e-12);  // the rest unchanged
    // Two rings deep: vertex 3 buried too is filled from 0 and 2 once 2 is.
    std::vector<glm::dvec3> H(8, glm::dvec3(0));
    H[0] = glm::dvec3(1), H[2] = glm::dvec3(1);
    std::vector<char> deep(8, 0);
    deep[4] = deep[6] = 1;
    fill_buried(tris, H, deep);
    EXPECT_NEAR(H[4].x, 1.0, 1e-12);
    EXPECT_NEAR(H[6].x, 1.0, 1e-12);
    // Nothing unburied near: left as gathered.
    std::vector<glm::dvec3> K(8, glm::dvec3(3));
    std::vector<char> all(8, 0);
    for (size_t u = 0; u < 8; u += 2) all[u] = 1;
    fill_buried(tris, K, all);
    EXPECT_NEAR(K[0].x, 3.0, 1e-12);
    EXPECT_EQ(all[0], 1);
}

TEST(Receivers, SmoothingAveragesNeighboursPerSide) {
    const std::vector<ReceiverMesh::Triangle> tris{{{0, 1, 2}, 1, 0}};
    std::vector<glm::dvec3> G(6, glm::dvec3(0));
    G[0] = glm::dvec3(2);  // vertex 0, front
    const auto S = smooth(tris, G);
    EXPECT_NEAR(S[0].x, 1.0, 1e-12);  // (1·2 + 0.5·0 + 0.5·0) / 2
    EXPECT_NEAR(S[2].x, 0.5, 1e-12);  // (0.5·2) / 2
    EXPECT_NEAR(S[1].x, 0.0, 1e-12);  // back sides do not mix with front sides
    // Neighbours whose value is not known (not gathered, no form factors) give nothing.
    std::vector<char> known(6, 1);
    known[2] = 0;  // vertex 1, front
    const auto K = smooth(tris, G, &known);
    EXPECT_NEAR(K[0].x, 2.0 / 1.5, 1e-12);  // (1·2 + 0.5·0) / 1.5
    EXPECT_NEAR(K[2].x, 0.5, 1e-12);        // its own value still counts: (0.5·2) / 2
}

}  // namespace
}  // namespace lumen::render::radiosity
