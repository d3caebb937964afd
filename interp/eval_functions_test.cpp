// User-defined functions called in expressions, and #declare with a directive as its value.
#include "interp/eval_test_support.hpp"

namespace lumen::interp::testing {
namespace {

using FunctionTest = EvalTest;

TEST_F(FunctionTest, FunctionsWithNamedAndDefaultParameters) {
    run("#declare F = function(a, b) { a * 2 + b }\n"
        "#declare G = function { x + y * z }\n"
        "#declare H = function(a) { F(a, 1) + G(1, 2, 3) }\n");
    EXPECT_DOUBLE_EQ(number("F(3, 4)"), 10);
    EXPECT_DOUBLE_EQ(number("G(1, 2, 3)"), 7);
    EXPECT_DOUBLE_EQ(number("H(2)"), 12);
    EXPECT_EQ(vec("x"), (std::vector<double>{1, 0, 0}));  // parameters do not leak
}

TEST_F(FunctionTest, UnevaluableFunctionsGiveErrors) {
    run("#declare P = function { pigment { rgb 1 } }\n"
        "#declare S = function { spline { spline { linear_spline 0, <0, 0, 0>, 1, <1, 1, 1> } } }\n"
        "#declare I = function { internal(61) }\n"
        "#declare F = function(a) { a }\n");
    // Without the renderer (these tests have none), pigment functions cannot run.
    EXPECT_EQ(expr_error("P(1, 2, 3)"),
              "expr:1:1: error: cannot evaluate function 'P' here: pigment and pattern functions "
              "need the renderer");
    EXPECT_EQ(expr_error("S(1, 2, 3)"), "expr:1:1: error: function 'S' takes 1 argument(s), found 3");
    EXPECT_EQ(error_of("#declare M = function { media { } }"),
              "test.pov:1:25: error: a function's body is an expression or a pigment, pattern, "
              "transform or spline block, not 'media'");
    EXPECT_EQ(expr_error("I(1, 2, 3)"), "expr:1:1: error: function 'I' takes 4 argument(s), found 3");
    EXPECT_EQ(expr_error("F(1, 2)"), "expr:1:1: error: function 'F' takes 1 argument(s), found 2");
}

// A call binds to the function as it was when the caller was declared (POV-Ray's rule), so a
// body naming its own identifier calls the earlier function: no recursion.
TEST_F(FunctionTest, CallsBindAtDeclaration) {
    run("#declare F = function { 1 }\n#declare F = function { F(x, y, z) + 1 }\n");
    EXPECT_DOUBLE_EQ(number("F(1, 2, 3)"), 2);
}

TEST_F(FunctionTest, DeclareWithADirectiveAsItsValue) {
    run("#declare Simple = 1;\n"
        "#declare A =\n#if (Simple) 10 #else 20 #end\n"
        "#declare B =\n#ifdef (Nope) <1,2,3> #else <4,5,6> #end\n");
    EXPECT_DOUBLE_EQ(num_var("A"), 10);
    EXPECT_EQ(components(var("B")), (std::vector<double>{4, 5, 6}));
    EXPECT_EQ(error_of("#declare C = #if (1) 1, 2 #end"),
              "test.pov:1:22: error: #declare needs one value (several are allowed only for layered textures)");
}

TEST_F(FunctionTest, DeprecatedDeclaresAreAccepted) {
    run("#declare deprecated once \"old name\" Old = 5;\n");
    EXPECT_DOUBLE_EQ(num_var("Old"), 5);
}

}  // namespace
}  // namespace lumen::interp::testing
