// parametric { } read as POV-Ray 3.7 reads it (interp/build_parametric.cpp).
#include "interp/build_test_support.hpp"

namespace lumen::interp::testing {
namespace {

using ParametricTest = BuildTest;

TEST_F(ParametricTest, ReadsFunctionsCornersAndOptions) {
    const auto p = shape_of<scene::Parametric>(
        "#declare F = function(u, v) { u * v }\n"
        "parametric { function { u }, function { F(u, v) } function { v } <2, 1>, <-1, 3>\n"
        "  contained_by { sphere { <0, 1, 0>, 3 } } accuracy 0.01 max_gradient 4\n"
        "  precompute 10, x, z }");
    for (const fn::ProgramPtr& f : p.functions) ASSERT_TRUE(f);
    EXPECT_EQ(p.uv_lo, glm::dvec2(-1, 1));  // corners sorted per component
    EXPECT_EQ(p.uv_hi, glm::dvec2(2, 3));
    EXPECT_TRUE(p.container.sphere);
    EXPECT_EQ(p.container.center, glm::dvec3(0, 1, 0));
    EXPECT_DOUBLE_EQ(p.accuracy, 0.01);
    EXPECT_DOUBLE_EQ(p.max_gradient, 4);
    EXPECT_EQ(p.precompute_depth, 10);
    EXPECT_EQ(p.precompute, (std::array<bool, 3>{true, false, true}));
    const auto d = shape_of<scene::Parametric>(
        "parametric { function { u } function { 0 } function { v } <0, 0>, <1, 1> }");
    EXPECT_FALSE(d.container.sphere);  // POV-Ray's default box -1..1
    EXPECT_EQ(d.container.lo, glm::dvec3(-1));
    EXPECT_DOUBLE_EQ(d.accuracy, 0.001);
    EXPECT_DOUBLE_EQ(d.max_gradient, 1);
    EXPECT_EQ(d.precompute_depth, 0);
}

TEST_F(ParametricTest, LocatedErrorsAndWarnings) {
    EXPECT_EQ(error_of("parametric { function { u } function { v } <0, 0>, <1, 1> }"),
              "t.pov:1:44: error: a parametric needs three functions: z is missing (function { ... })");
    EXPECT_EQ(error_of("parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> "
                       "precompute 21 }"),
              "t.pov:1:85: error: Precompute: invalid depth (1 to 20)");
    EXPECT_EQ(error_of("parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> "
                       "precompute 5, z, x }"),
              "t.pov:1:91: error: precompute takes x, y and z, in that order");
    warnings.clear();
    run("parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> accuracy 0 }");
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0].message, "a parametric's accuracy must be above 0: using 0.001");
}

}  // namespace
}  // namespace lumen::interp::testing
