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

// A call binds to the function as it was when the caller was declared (POV-Ray's rule): G
// keeps the F it was declared with after F is undefined and declared anew (povray: 2 and 5).
TEST_F(FunctionTest, CallsBindAtDeclaration) {
    run("#declare F = function { 1 }\n#declare G = function { F(x, y, z) + 1 }\n#undef F\n"
        "#declare F = function { 5 }\n");
    EXPECT_DOUBLE_EQ(number("G(1, 2, 3)"), 2);
    EXPECT_DOUBLE_EQ(number("F(1, 2, 3)"), 5);
}

// POV-Ray's rules, probed with povray 3.7: a function keeps its name until #undef, another
// identifier does not become a function, and a macro's #local binds a fresh name.
TEST_F(FunctionTest, FunctionsAreNotRedeclared) {
    EXPECT_EQ(error_of("#declare F = function { x }\n#declare F = function { y }"),
              "test.pov:2:10: error: Redeclaring functions is not allowed - #undef the function first!");
    EXPECT_EQ(error_of("#declare G = function { x }\n#declare G = 1;"),
              "test.pov:2:10: error: Redeclaring functions is not allowed - #undef the function first!");
    EXPECT_EQ(error_of("#declare H = function { x }\n#local H = function { y }"),
              "test.pov:2:8: error: Redeclaring functions is not allowed - #undef the function first!");
    EXPECT_EQ(error_of("#declare K = 1;\n#declare K = function { y }"),
              "test.pov:2:10: error: Attempted to redefine float identifier as function identifier.");
    run("#declare U = function { x }\n#undef U\n#declare U = function { y }\n"
        "#macro M() #local L = function { y } L(1, 2, 3) #end\n"
        "#declare A = M();\n#declare B = M();\n");
    EXPECT_DOUBLE_EQ(number("U(1, 2, 3)"), 2);
    EXPECT_DOUBLE_EQ(num_var("B"), 2);
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
