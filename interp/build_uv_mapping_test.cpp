// uv_mapping as the interpreter reads it: where POV-Ray accepts the keyword, what it marks,
// which transforms reach a uv-mapped texture, and the uv data of meshes and patches.
#include "interp/build_test_support.hpp"

namespace lumen::interp::testing {
namespace {

class BuildUvMapping : public BuildTest {
protected:
    scene::Mesh mesh_of(const std::string& text) { return shape_of<scene::Mesh>(text); }
};

TEST_F(BuildUvMapping, MarksPigmentNormalAndTexture) {
    scene::Texture p = texture_of("sphere { 0, 1 pigment { uv_mapping checker } }");
    EXPECT_TRUE(p.pigment->pattern.uv_mapping);
    EXPECT_FALSE(p.pattern.uv_mapping);
    scene::Texture n = texture_of("sphere { 0, 1 normal { uv_mapping bumps } }");
    EXPECT_TRUE(n.normal->pattern.uv_mapping);
    scene::Texture t = texture_of("sphere { 0, 1 texture { uv_mapping pigment { checker } } }");
    EXPECT_TRUE(t.pattern.uv_mapping);
    EXPECT_FALSE(t.pigment->pattern.uv_mapping);
}

TEST_F(BuildUvMapping, FollowsAnIdentifierOrPrecedesOne) {
    const std::string decl = "#declare P = pigment { checker scale 2 }\n";
    for (const char* body : {"P uv_mapping", "uv_mapping P"}) {
        scene::Texture t = texture_of(decl + "sphere { 0, 1 pigment { " + body + " } }");
        EXPECT_TRUE(t.pigment->pattern.uv_mapping) << body;
        // P's own scale stays: it acts in uv space.
        EXPECT_DOUBLE_EQ(t.pigment->pattern.steps.composed_transform().m[0][0], 2) << body;
    }
}

TEST_F(BuildUvMapping, AnywhereLaterIsALocatedError) {
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { checker uv_mapping } }"),
              "t.pov:1:33: error: uv_mapping must come first in its block (after an identifier)");
    EXPECT_NE(error_of("sphere { 0, 1 normal { bumps uv_mapping } }").find("must come first"),
              std::string::npos);
    EXPECT_NE(error_of("sphere { 0, 1 texture { pigment { rgb 1 } uv_mapping } }").find("must come first"),
              std::string::npos);
}

TEST_F(BuildUvMapping, OuterTransformsDoNotReachIt) {
    scene::Texture t = texture_of(
        "sphere { 0, 1 pigment { uv_mapping checker scale 0.5 } scale 3 translate x }");
    const scene::Transform own = t.pigment->pattern.steps.composed_transform();
    EXPECT_DOUBLE_EQ(own.m[0][0], 0.5);
    EXPECT_DOUBLE_EQ(own.m[3][0], 0);
    // A plain pigment beside it still moves with the object.
    scene::Texture plain = texture_of("sphere { 0, 1 pigment { checker scale 0.5 } scale 3 }");
    EXPECT_DOUBLE_EQ(plain.pigment->pattern.steps.composed_transform().m[0][0], 1.5);
}

TEST_F(BuildUvMapping, TexturesOwnTransformsActInUvSpace) {
    scene::Texture t = texture_of(
        "sphere { 0, 1 texture { uv_mapping pigment { checker } scale 0.25 } scale 4 }");
    EXPECT_DOUBLE_EQ(t.pigment->pattern.steps.composed_transform().m[0][0], 0.25);
}

TEST_F(BuildUvMapping, ObjectLevelMapsLaterTextures) {
    scene::ObjectPtr o = first_object(
        "sphere { 0, 1 uv_mapping pigment { checker scale 0.5 } finish { ambient 1 } scale 2 }");
    ASSERT_EQ(o->texture.size(), 1u);
    EXPECT_TRUE(o->texture[0]->pattern.uv_mapping);
    EXPECT_DOUBLE_EQ(o->texture[0]->pigment->pattern.steps.composed_transform().m[0][0], 0.5);
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { checker } uv_mapping }"),
              "t.pov:1:35: error: uv_mapping must be specified before the texture");
}

TEST_F(BuildUvMapping, MeshTrianglesCarryTheirUvs) {
    scene::Mesh m = mesh_of(
        "mesh { triangle { 0, x, y uv_vectors <0.5, 1>, 2, <0, 0.25> } triangle { 0, x, z } }");
    ASSERT_EQ(m.faces.size(), 2u);
    const auto& f = m.faces[0];
    EXPECT_EQ(m.uvs[f.uv[0]], glm::dvec2(0.5, 1));
    EXPECT_EQ(m.uvs[f.uv[1]], glm::dvec2(2, 2));
    EXPECT_EQ(m.uvs[f.uv[2]], glm::dvec2(0, 0.25));
    EXPECT_EQ(m.uvs[m.faces[1].uv[1]], glm::dvec2(0, 0));  // POV-Ray's default
}

TEST_F(BuildUvMapping, Mesh2UvIndices) {
    const std::string verts = "vertex_vectors { 3, 0, x, y } ";
    scene::Mesh same = mesh_of("mesh2 { " + verts +
                               "uv_vectors { 3, <0,0>, <1,0>, <0,1> } face_indices { 1, <2,1,0> } }");
    EXPECT_EQ(same.faces[0].uv, (std::array<int, 3>{2, 1, 0}));
    scene::Mesh one = mesh_of("mesh2 { " + verts + "uv_vectors { 1, <0.5,0> } face_indices { 1, <0,1,2> } }");
    EXPECT_EQ(one.faces[0].uv, (std::array<int, 3>{0, 0, 0}));
    scene::Mesh given = mesh_of("mesh2 { " + verts +
                                "uv_vectors { 2, <0,0>, <1,0> } face_indices { 1, <0,1,2> } "
                                "uv_indices { 1, <1,0,0> } }");
    EXPECT_EQ(given.faces[0].uv, (std::array<int, 3>{1, 0, 0}));
    scene::Mesh none = mesh_of("mesh2 { " + verts + "face_indices { 1, <0,1,2> } }");
    EXPECT_EQ(none.faces[0].uv, (std::array<int, 3>{-1, -1, -1}));
}

TEST_F(BuildUvMapping, Mesh2UvErrorsAreLocated) {
    const std::string verts = "mesh2 { vertex_vectors { 3, 0, x, y } uv_vectors { 2, <0,0>, <1,0> } ";
    EXPECT_NE(error_of(verts + "face_indices { 1, <0,1,2> } }").find("t.pov:1:1: error: mesh2 needs uv_indices"),
              std::string::npos);
    EXPECT_NE(error_of(verts + "face_indices { 1, <0,1,2> } uv_indices { 1, <0,1,5> } }")
                  .find("uv index 5 out of range"),
              std::string::npos);
    EXPECT_NE(error_of(verts + "face_indices { 2, <0,1,2>, <0,2,1> } uv_indices { 1, <0,1,1> } }")
                  .find("uv_indices count differs"),
              std::string::npos);
}

TEST_F(BuildUvMapping, BicubicPatchKeepsItsParametersAndCorners) {
    const std::string points = "<0,0,0>,<1,0,0>,<2,0,0>,<3,0,0>, <0,1,0>,<1,1,0>,<2,1,0>,<3,1,0>, "
                               "<0,2,0>,<1,2,0>,<2,2,0>,<3,2,0>, <0,3,0>,<1,3,0>,<2,3,0>,<3,3,0>";
    scene::Mesh plain = mesh_of("bicubic_patch { type 1 u_steps 1 v_steps 1 " + points + " }");
    EXPECT_EQ(plain.patch_corners, (std::vector<glm::dvec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}));
    ASSERT_EQ(plain.uvs.size(), plain.vertices.size());
    for (size_t i = 0; i < plain.uvs.size(); ++i) {
        // Vertex P(4i + j) of the patch sits at (x, y) = (j, i): parameters (u, v) = (y, x)/3.
        EXPECT_DOUBLE_EQ(plain.uvs[i].x, plain.vertices[i].y / 3);
        EXPECT_DOUBLE_EQ(plain.uvs[i].y, plain.vertices[i].x / 3);
    }
    scene::Mesh mapped = mesh_of("bicubic_patch { type 1 uv_vectors <0,0>, <2,0>, <2,2>, <0,2> " +
                                 points + " }");
    EXPECT_EQ(mapped.patch_corners, (std::vector<glm::dvec2>{{0, 0}, {2, 0}, {2, 2}, {0, 2}}));
}

}  // namespace
}  // namespace lumen::interp::testing
