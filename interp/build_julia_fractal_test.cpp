// julia_fractal through the interpreter: its keywords, defaults and POV-Ray's refusals.
#include <cmath>

#include "interp/build_test_support.hpp"

namespace lumen::interp::testing {
namespace {

using BuildJulia = BuildTest;
using scene::JuliaAlgebra;
using scene::JuliaFunction;

TEST_F(BuildJulia, DefaultsAreQuaternionSqr) {
    auto j = shape_of<scene::JuliaFractal>("julia_fractal { <-0.08, 0.7, 0, 0> }");
    EXPECT_DOUBLE_EQ(j.c[0], -0.08);
    EXPECT_DOUBLE_EQ(j.c[1], 0.7);
    EXPECT_EQ(j.algebra, JuliaAlgebra::Quaternion);
    EXPECT_EQ(j.function, JuliaFunction::Sqr);
    EXPECT_EQ(j.max_iteration, 20);
    EXPECT_DOUBLE_EQ(j.precision, 20);
    EXPECT_DOUBLE_EQ(j.slice[3], 1);
    EXPECT_DOUBLE_EQ(j.slice_distance, 0);
    // 1 + |c| + 1e-7, at most 2.
    EXPECT_NEAR(j.bound_radius(), 1 + std::hypot(0.08, 0.7), 1e-6);
}

TEST_F(BuildJulia, KeywordsInAnyOrderAndTheSliceNormalised) {
    auto j = shape_of<scene::JuliaFractal>(
        "julia_fractal { <0.4, 0.2, 0.1, 0> slice <0, 0, 3, 4>, 0.5 max_iteration 7.9 "
        "hypercomplex cos precision 0.3 pigment { rgb 1 } }");
    EXPECT_EQ(j.algebra, JuliaAlgebra::Hypercomplex);
    EXPECT_EQ(j.function, JuliaFunction::Cos);
    EXPECT_EQ(j.max_iteration, 7);   // truncated
    EXPECT_DOUBLE_EQ(j.precision, 1);  // under 1 counts as 1
    EXPECT_DOUBLE_EQ(j.slice[2], 0.6);
    EXPECT_DOUBLE_EQ(j.slice[3], 0.8);
    EXPECT_DOUBLE_EQ(j.slice_distance, 0.5);
    EXPECT_DOUBLE_EQ(j.bound_radius(), 4);
    EXPECT_DOUBLE_EQ(j.exit_value(), 16);
    auto p = shape_of<scene::JuliaFractal>(
        "#declare A = 2; julia_fractal { <0.4, 0.2, 0.1, 0> hypercomplex pwr(A, -0.5) }");
    EXPECT_EQ(p.function, JuliaFunction::Pwr);
    EXPECT_DOUBLE_EQ(p.exponent.x, 2);
    EXPECT_DOUBLE_EQ(p.exponent.y, -0.5);
    auto c = shape_of<scene::JuliaFractal>("julia_fractal { <0.4, 0.2, 0.1, 0> cube sqr }");
    EXPECT_EQ(c.function, JuliaFunction::Sqr);  // the last function given wins
}

TEST_F(BuildJulia, BadInputIsALocatedError) {
    // POV-Ray: "Illegal function: quaternion only supports sqr and cube", checked once the
    // block is read, so the order of the keywords does not matter.
    EXPECT_EQ(error_of("julia_fractal { <1, 0, 0, 0> quaternion sin }"),
              "t.pov:1:41: error: illegal function: quaternion only supports sqr and cube");
    EXPECT_EQ(error_of("julia_fractal { <1, 0, 0, 0> reciprocal quaternion }"),
              "t.pov:1:30: error: illegal function: quaternion only supports sqr and cube");
    // POV-Ray: "Slice vector is zero." (|n|^2 < 1e-10) and "Slice t component is zero."
    // (|t| < 1e-10 before normalising).
    EXPECT_EQ(error_of("julia_fractal { <1, 0, 0, 0> slice <1e-6, 0, 0, 0>, 0 }"),
              "t.pov:1:30: error: julia_fractal slice vector is zero");
    EXPECT_EQ(error_of("julia_fractal { <1, 0, 0, 0> slice <1, 0, 0, 5e-11>, 0 }"),
              "t.pov:1:30: error: julia_fractal slice t component is zero (w would be "
              "undefined)");
    EXPECT_EQ(error_of("julia_fractal { <1, 0, 0, 0> hypercomplex pwr }"),
              "t.pov:1:43: error: pwr needs its exponent: pwr(a, b)");
    EXPECT_EQ(error_of("julia_fractal { <1, 0, 0, 0, 1> }"),
              "t.pov:1:17: error: julia_fractal needs a 4-D vector here");
    // The fractal's keywords come before the object modifiers, as in POV-Ray.
    EXPECT_NE(error_of("julia_fractal { <1, 0, 0, 0> pigment { rgb 1 } max_iteration 5 }"), "");
}

TEST_F(BuildJulia, CsgChildrenAreMarked) {
    // POV-Ray's child objects list every crossing; a stand-alone fractal only its first.
    auto o = first_object(
        "#declare J = julia_fractal { <0.4, 0.2, 0.1, 0> }\n"
        "intersection { object { J } sphere { 0, 1 } }");
    const auto& csg = std::get<scene::Csg>(o->shape);
    ASSERT_EQ(csg.children.size(), 2u);
    EXPECT_TRUE(std::get<scene::JuliaFractal>(csg.children[0]->shape).csg_child);
    EXPECT_FALSE(shape_of<scene::JuliaFractal>("julia_fractal { <0.4, 0.2, 0.1, 0> }").csg_child);
}

TEST_F(BuildJulia, MaxIterationIsBounded) {
    auto j = shape_of<scene::JuliaFractal>("julia_fractal { <1, 0, 0, 0> max_iteration 1e9 }");
    EXPECT_EQ(j.max_iteration, 4096);
    auto z = shape_of<scene::JuliaFractal>("julia_fractal { <1, 0, 0, 0> max_iteration -3 }");
    EXPECT_EQ(z.max_iteration, 0);  // POV-Ray draws nothing then
}

}  // namespace
}  // namespace lumen::interp::testing
