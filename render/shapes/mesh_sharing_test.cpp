// Copies of one mesh share one prepared mesh (shared_mesh), each traced in its own place, and
// a copy that differs (its own textures, another inside_vector) gets its own.
#include <gtest/gtest.h>

#include "render/geometry_test_util.hpp"
#include "render/shapes/mesh.hpp"
#include "render/shapes/shape_data.hpp"

namespace lumen::render {
namespace {

using namespace testing;

// A unit square in z = 0 as two triangles, enough faces for the tree to be built.
scene::Mesh square_mesh(int n = 16) {
    scene::Mesh m;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) m.vertices.push_back({double(i) / n, double(j) / n, 0});
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            scene::Mesh::Face f;
            f.v = {a, b, d};
            m.faces.push_back(f);
            f.v = {a, d, c};
            m.faces.push_back(f);
        }
    return m;
}

const MeshShape* prepared(const scene::Mesh& m, ShapeData& keep) {
    EXPECT_TRUE(prepare_shape(scene::Shape(m), true, keep));
    return std::get<MeshPtr>(keep).get();
}

TEST(MeshSharing, CopiesShareOnePreparedMeshUntilTheyDiffer) {
    const scene::Mesh original = square_mesh();
    const scene::Mesh copy = original;
    ShapeData a, b, c, d;
    const MeshShape* pa = prepared(original, a);
    EXPECT_EQ(prepared(copy, b), pa);
    scene::Mesh other_inside = original;
    other_inside.inside_vector = glm::dvec3(0, 0, 1);
    EXPECT_NE(prepared(other_inside, c), pa);
    scene::Mesh textured = original;  // its textures written: no longer the same mesh
    textured.textures.push_back(some_texture());
    EXPECT_NE(prepared(textured, d), pa);
    // A rebuilt mesh with equal values is another mesh (nothing is compared by value).
    ShapeData e;
    EXPECT_NE(prepared(square_mesh(), e), pa);
}

TEST(MeshSharing, ACopyIsTracedInItsOwnPlace) {
    const scene::Mesh m = square_mesh();
    Geometry g(scene_of({make(m, translate({0, 0, 2})), make(m, translate({5, 0, 3}))}));
    const auto near = trace(g, ray({0.3, 0.6, -1}, {0, 0, 1}));
    ASSERT_TRUE(near);
    EXPECT_NEAR(near->t, 3, 1e-9);
    const auto far = trace(g, ray({5.3, 0.6, -1}, {0, 0, 1}));
    ASSERT_TRUE(far);
    EXPECT_NEAR(far->t, 4, 1e-9);
    EXPECT_FALSE(trace(g, ray({2.5, 0.5, -1}, {0, 0, 1})));
}

TEST(MeshSharing, APreparedMeshOutlivesTheSceneMeshItCameFrom) {
    ShapeData keep;
    {
        const scene::Mesh m = square_mesh();
        prepared(m, keep);
    }
    ShapeHit h;
    EXPECT_TRUE(intersect(std::get<MeshPtr>(keep), {{0.5, 0.5, -1}, {0, 0, 1}}, 1e-6, 1e30, h));
    EXPECT_NEAR(h.t, 1, 1e-12);
}

}  // namespace
}  // namespace lumen::render
