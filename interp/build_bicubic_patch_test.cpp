// bicubic_patch through the interpreter: POV-Ray's subdivision into a smooth mesh (leaf counts
// by flatness and steps), its keywords, the old header form and the located errors.
#include <cmath>

#include <glm/geometric.hpp>

#include "interp/build_test_support.hpp"

namespace lumen::interp::testing {
namespace {


// A flat and a curved net (the curved one bulges in y in its middle).
const char* kFlat =
    "<0,0,0>,<1,0,0>,<2,0,0>,<3,0,0>, <0,0,1>,<1,0,1>,<2,0,1>,<3,0,1>, "
    "<0,0,2>,<1,0,2>,<2,0,2>,<3,0,2>, <0,0,3>,<1,0,3>,<2,0,3>,<3,0,3>";
const char* kCurved =
    "<0,0,0>,<1,0,0>,<2,0,0>,<3,0,0>, <0,0,1>,<1,1,1>,<2,1,1>,<3,0,1>, "
    "<0,0,2>,<1,1,2>,<2,1,2>,<3,0,2>, <0,0,3>,<1,0,3>,<2,0,3>,<3,0,3>";

class BuildBicubicPatch : public BuildTest {
protected:
    scene::Mesh patch(const std::string& header, const char* net, const std::string& after = "") {
        return shape_of<scene::Mesh>("bicubic_patch { " + header + " " + net + " " + after + " }");
    }
};

TEST_F(BuildBicubicPatch, FlatnessZeroSubdividesToTheSteps) {
    // Two triangles per leaf; 4^steps leaves when both steps are equal.
    EXPECT_EQ(patch("type 1 u_steps 3 v_steps 3", kCurved).faces.size(), 2u * 64);
    EXPECT_EQ(patch("type 0 u_steps 2 v_steps 2", kCurved).faces.size(), 2u * 16);
    // Unequal steps halve only along the parameter with steps left.
    EXPECT_EQ(patch("type 1 u_steps 1 v_steps 3", kCurved).faces.size(), 2u * (2 * 8));
    EXPECT_EQ(patch("type 1", kCurved).faces.size(), 2u);
}

TEST_F(BuildBicubicPatch, AFlatNetStopsAtTheFirstLeafOnceFlatnessIsPositive) {
    EXPECT_EQ(patch("type 1 flatness 0.01 u_steps 5 v_steps 5", kFlat).faces.size(), 2u);
    // The curved net is flat only to a coarser tolerance.
    const size_t fine = patch("type 1 flatness 0.01 u_steps 5 v_steps 5", kCurved).faces.size();
    const size_t coarse = patch("type 1 flatness 0.2 u_steps 5 v_steps 5", kCurved).faces.size();
    EXPECT_GT(fine, coarse);
    EXPECT_GT(coarse, 2u);
}

TEST_F(BuildBicubicPatch, FlatnessIsMeasuredAfterTheObjectTransform) {
    // POV-Ray subdivides the transformed patch: scaling it up makes the same net less flat.
    const size_t plain = patch("type 1 flatness 0.2 u_steps 5 v_steps 5", kCurved).faces.size();
    const size_t scaled =
        patch("type 1 flatness 0.2 u_steps 5 v_steps 5", kCurved, "scale 4").faces.size();
    EXPECT_GT(scaled, plain);
}

TEST_F(BuildBicubicPatch, CornersLieOnThePatchWithItsExactNormals) {
    const scene::Mesh m = patch("type 1 u_steps 2 v_steps 2", kCurved);
    ASSERT_EQ(m.vertices.size(), m.normals.size());
    for (size_t i = 0; i < m.vertices.size(); ++i) {
        EXPECT_NEAR(glm::length(m.normals[i]), 1, 1e-12);
        EXPECT_GE(m.vertices[i].y, -1e-12);  // the bulge stays above the border's plane
        EXPECT_LE(m.vertices[i].y, 0.5625 + 1e-12);
    }
    // At the middle of the patch the surface is at y = 0.5625 (the Bernstein weights 3/8 + 3/8, squared) and its normal is ±y.
    bool centre = false;
    for (size_t i = 0; i < m.vertices.size(); ++i)
        if (glm::length(m.vertices[i] - glm::dvec3(1.5, 0.5625, 1.5)) < 1e-12) {
            centre = true;
            EXPECT_NEAR(std::fabs(m.normals[i].y), 1, 1e-12);
        }
    EXPECT_TRUE(centre);
}

TEST_F(BuildBicubicPatch, OldHeaderFormAndTypes) {
    // `T US VS`: flatness 0.1 for types 0 and 1, read for types 2 and 3 (which render as 1).
    EXPECT_EQ(patch("1 2 2", kFlat).faces.size(), 2u);  // flat: one leaf
    EXPECT_EQ(patch("3 0 2 2", kCurved).faces.size(), 2u * 16);
    EXPECT_FALSE(warnings.empty());
}

TEST_F(BuildBicubicPatch, DegenerateNetsGiveNoTrianglesAndNoNaN) {
    std::string same;
    for (int i = 0; i < 16; ++i) same += (i ? ", " : "") + std::string("<1,2,3>");
    EXPECT_TRUE(shape_of<scene::Mesh>("bicubic_patch { type 1 u_steps 3 v_steps 3 " + same + " }")
                    .faces.empty());
    std::string line;
    for (int i = 0; i < 16; ++i) line += (i ? ", " : "") + std::string("<") + std::to_string(i) + ",0,0>";
    const scene::Mesh m = shape_of<scene::Mesh>("bicubic_patch { type 1 u_steps 2 v_steps 2 " + line + " }");
    EXPECT_TRUE(m.faces.empty());
    for (const glm::dvec3& n : m.normals) EXPECT_TRUE(std::isfinite(n.x + n.y + n.z));
}

TEST_F(BuildBicubicPatch, LocatedErrors) {
    EXPECT_NE(error_of(std::string("bicubic_patch { u_steps 2 ") + kFlat + " }").find("needs its type"),
              std::string::npos);
    EXPECT_NE(error_of(std::string("bicubic_patch { type 1 u_steps 11 ") + kFlat + " }").find("u_steps"),
              std::string::npos);
    EXPECT_NE(error_of("bicubic_patch { type 1 <0,0,0>, <1,0,0> }").find("t.pov:1:"),
              std::string::npos);  // too few points
    EXPECT_NE(error_of(std::string("bicubic_patch { type 7 ") + kFlat + " }").find("type must be"),
              std::string::npos);
}

}  // namespace
}  // namespace lumen::interp::testing
