// Functions compiled at their declaration (compile_function.cpp) and run by the function VM,
// against values POV-Ray 3.7.0.10 prints with #debug str(F(...), 0, 17) for the same
// declarations (probe run 2026-12-05).
#include <cmath>

#include "interp/eval_test_support.hpp"

namespace lumen::interp::testing {
namespace {

using CompiledFunctionTest = EvalTest;

TEST_F(CompiledFunctionTest, ArithmeticAsPovRaysCompilerRewritesIt) {
    run("#declare D = function { x / 3 }\n"
        "#declare W = function { pow(x, 7) + pow(y, 0.5) + 1.5 * 2 - z }\n"
        "#declare Q = function(u, v) { x * 10 + y }\n"
        "#declare Z = function(a, b, c) { x }\n");
    // Division by a constant is multiplication by its reciprocal: 1.66666666666666652, not
    // SDL's 5 / 3 = 1.6666666666666667.
    EXPECT_EQ(number("D(5, 0, 0)"), 5 * (1.0 / 3));
    EXPECT_NE(number("D(5, 0, 0)"), 5.0 / 3);
    // pow(e, 7) is ((e²)²·e)·e² (POV: 3.36293066237309635).
    const double b = 1.1, b2 = b * b, b4 = b2 * b2;
    EXPECT_EQ(number("W(1.1, 2, 3)"), b4 * b * b2 + std::pow(2.0, 0.5) + 3 - 3);
    EXPECT_DOUBLE_EQ(number("W(1.1, 2, 3)"), 3.36293066237309635);
    // x and u share a slot, y and v another; a slot no parameter names reads 0.
    EXPECT_EQ(number("Q(1, 2)"), 12);
    EXPECT_EQ(number("Z(1, 2, 3)"), 0);
}

TEST_F(CompiledFunctionTest, SelectSumProdComparisonsAndLogic) {
    run("#declare S = function { select(x, 10, 20, 30) }\n"
        "#declare T = function { select(x, 1, 2) }\n"
        "#declare P = function { prod(i, 1, x, i) + sum(i, 0.5, 3, i) }\n"
        "#declare C = function { (x = 1) + (x < 2) * 10 + (x != 1) * 100 + (y >= 3) * 1000 }\n"
        "#declare H = function { 1 | 0 & 0 }\n"
        "#declare E = function { (x = 1.0000000000001) }\n");
    EXPECT_EQ(number("S(-1, 0, 0)"), 10);
    EXPECT_EQ(number("S(0, 0, 0)"), 20);
    EXPECT_EQ(number("S(2, 0, 0)"), 30);
    EXPECT_EQ(number("T(-0.5, 0, 0)"), 1);
    EXPECT_EQ(number("T(0, 0, 0)"), 2);
    EXPECT_EQ(number("P(5, 0, 0)"), 124.5);  // 5! + 0.5 + 1.5 + 2.5
    EXPECT_EQ(number("C(1, 3, 0)"), 1011);
    EXPECT_EQ(number("H(0, 0, 0)"), 1);  // & binds tighter than | in functions (SDL: 0)
    EXPECT_EQ(number("E(1, 0, 0)"), 0);  // exact comparison (SDL's has a 1e-10 tolerance)
}

TEST_F(CompiledFunctionTest, MathCallsCapturedValuesAndInternals) {
    run("#include \"functions.inc\"\n"
        "#declare M = function { min(x, y, z) + max(x, 2) + div(7, x) + mod(7.5, x) + int(-2.5)"
        " + log(100) + degrees(pi) }\n"
        "#declare A = 2.5;\n"
        "#declare K = function { x * A + f_sphere(x, y, z, 1) + f_noise3d(x, y, z) }\n"
        "#declare A = 100;\n"
        "#declare N = function { sqrt(x) + 1 }\n");
    EXPECT_DOUBLE_EQ(number("M(2, -1, 3)"), 185.5);
    // A is copied in at the declaration: the later 100 does not change K.
    EXPECT_DOUBLE_EQ(number("K(0.3, 0.4, 0.5)"), 0.93297804811993434);
    EXPECT_TRUE(std::isnan(number("N(-1, 0, 0)")));
}

// Each pow(e, 2..8) and select(a, b, c, d) takes a local only while its code runs: a long
// body of them compiles (the VM has 16 locals).
TEST_F(CompiledFunctionTest, TemporariesAreGivenBack) {
    std::string body = "0";
    for (int i = 0; i < 40; ++i) body += " + pow(x, 4) + select(y, 1, 2, 3)";
    run("#declare F = function { " + body + " }\n");
    EXPECT_DOUBLE_EQ(number("F(2, 0, 0)"), 40 * (16 + 2));
    // Nesting does use them up: six sums take 18 of the 16.
    std::string nested = "1";
    for (char v : std::string("abcdef")) nested = std::string("sum(") + v + ", 0, 0, " + nested + ")";
    EXPECT_NE(error_of("#declare G = function { " + nested + " }").find("too many nested"),
              std::string::npos);
}

TEST_F(CompiledFunctionTest, LocatedErrorsForWhatFunctionsCannotDo) {
    EXPECT_EQ(error_of("#declare F = function { x ? 1 : 2 }"),
              "test.pov:1:25: error: '? :' is not available in functions (use select())");
    EXPECT_EQ(error_of("#declare F = function { !x }"),
              "test.pov:1:25: error: '!' is not available in functions (write 1 - (a != 0))");
    EXPECT_EQ(error_of("#declare F = function { x / 0 }"),
              "test.pov:1:29: error: division by zero");
    EXPECT_EQ(error_of("#declare V = <1, 2, 3>;\n#declare F = function { V }"),
              "test.pov:2:25: error: 'V' is a vector: a function can only use float identifiers "
              "and other functions");
    EXPECT_EQ(error_of("#declare F = function { rand(x) }").substr(0, 40),
              "test.pov:1:25: error: 'rand' cannot be c");
    EXPECT_EQ(error_of("#declare G = function(a) { a }\n#declare F = function { G(x, y) }"),
              "test.pov:2:25: error: function 'G' takes 1 argument(s), found 2");
    // POV-Ray takes 56 parameters and stops at 57 ("Missing {").
    std::string params = "p0";
    for (int i = 1; i < 57; ++i) params += ", p" + std::to_string(i);
    EXPECT_EQ(error_of("#declare F = function(" + params + ") { p0 }"),
              "test.pov:1:14: error: a function takes at most 56 parameters, as in POV-Ray; this "
              "one names 57");
    EXPECT_EQ(error_of("#declare F = function(" + params.substr(0, params.rfind(',')) + ") { p55 }"), "");
    // A pattern is given x, y, z only: a function of four parameters cannot be one.
    EXPECT_EQ(error_of("#declare P4 = function(a, b, c, d) { a }\nsphere { 0, 1 pigment { P4 } }"),
              "test.pov:2:25: error: a pattern function is given x, y and z: this one takes 4 "
              "parameters");
}

}  // namespace
}  // namespace lumen::interp::testing
