// POV-Ray's domain rules for the math built-ins and division (interp/math_builtins.cpp lists
// what povray 3.7 does for each): errors where it stops, its warning and value where it warns,
// and a warning from lumen wherever POV-Ray lets an inf or nan appear silently.
#include <cmath>

#include "interp/eval_test_support.hpp"

namespace lumen::interp::testing {
namespace {

using MathDomainTest = EvalTest;

TEST_F(MathDomainTest, ErrorsWherePovRayStops) {
    const std::pair<const char*, const char*> cases[] = {
        {"sqrt(-1)", "expr:1:6: error: sqrt of a negative number (-1)"},
        {"sqrt(-1e-30)", "expr:1:6: error: sqrt of a negative number (-1e-30)"},
        {"ln(0)", "expr:1:4: error: ln of zero or a negative number (0)"},
        {"ln(-1)", "expr:1:4: error: ln of zero or a negative number (-1)"},
        {"log(0)", "expr:1:5: error: log of zero or a negative number (0)"},
        {"atan2(0,0)", "expr:1:1: error: atan2(0, 0) is undefined: both arguments are within 1e-10 of 0"},
        // POV's tolerance includes 1e-10 itself
        {"atan2(1e-10,0)", "expr:1:1: error: atan2(1e-10, 0) is undefined: both arguments are within 1e-10 of 0"},
        {"pow(0,0)", "expr:1:1: error: pow(0, 0) is undefined"},
    };
    for (const auto& [expr, error] : cases) EXPECT_EQ(expr_error(expr), error);
    EXPECT_TRUE(messages.empty());
}

TEST_F(MathDomainTest, NearTheEdgeOfTheDomainIsFine) {
    EXPECT_DOUBLE_EQ(number("sqrt(-0)"), 0);
    EXPECT_NEAR(number("ln(1e-300)"), -690.7755279, 1e-6);
    EXPECT_DOUBLE_EQ(number("atan2(0,1.1e-10)"), 0);
    EXPECT_DOUBLE_EQ(number("pow(0,1e-30)"), 0);
    EXPECT_DOUBLE_EQ(number("pow(1e-30,0)"), 1);
    EXPECT_TRUE(messages.empty());
}

TEST_F(MathDomainTest, AcosAndAsinClampWithAWarning) {
    EXPECT_DOUBLE_EQ(number("acos(2)"), 0);
    EXPECT_DOUBLE_EQ(number("acos(-2)"), std::acos(-1.0));
    EXPECT_DOUBLE_EQ(number("asin(2)"), std::asin(1.0));
    EXPECT_DOUBLE_EQ(number("asin(-1.0000000001)"), -std::asin(1.0));
    ASSERT_EQ(messages.size(), 4u);
    EXPECT_EQ(messages[0].severity, Severity::Warning);
    EXPECT_EQ(format_headline(messages[0]),
              "expr:1:6: warning: domain error in acos: 2 is outside -1..1, 1 used instead (as POV-Ray does)");
}

TEST_F(MathDomainTest, DivisionByZeroIsPlusInfinityWithAWarning) {
    for (const char* e : {"1/0", "-1/0", "0/0"}) {
        messages.clear();
        EXPECT_EQ(number(e), HUGE_VAL) << e;
        ASSERT_EQ(messages.size(), 1u) << e;
        EXPECT_EQ(messages[0].message, "division by zero gives inf");
    }
    EXPECT_EQ(number("-(1/0)"), -HUGE_VAL);
    const std::vector<double> v = vec("<1,2,3>/<1,0,1>");
    EXPECT_EQ(v[0], 1);
    EXPECT_EQ(v[1], HUGE_VAL);
    EXPECT_EQ(v[2], 3);
}

TEST_F(MathDomainTest, IntAndDivTakePovRaysThirtyTwoBitValue) {
    EXPECT_DOUBLE_EQ(number("int(-2.7)"), -2);
    EXPECT_DOUBLE_EQ(number("int(1e10)"), -2147483648.0);
    EXPECT_DOUBLE_EQ(number("int(-1e10)"), -2147483648.0);
    EXPECT_TRUE(messages.empty());
    EXPECT_DOUBLE_EQ(number("div(1,0)"), -2147483648.0);
    ASSERT_EQ(messages.size(), 1u);
    EXPECT_EQ(messages[0].message, "div() by zero gives -2147483648 (as in POV-Ray)");
}

// POV-Ray gives these silently; lumen gives POV's value and says where the inf or nan began.
TEST_F(MathDomainTest, SilentInfinityOrNanGetsAWarning) {
    struct Case { const char* expr; const char* message; };
    for (const Case& c : {Case{"pow(0,-1)", "'pow' gives inf here"}, Case{"pow(-8,1/3)", "'pow' gives nan here"},
                          Case{"mod(1,0)", "'mod' gives nan here"}, Case{"exp(1000)", "'exp' gives inf here"},
                          Case{"1e300*1e300", "'*' overflows to inf here"},
                          Case{"1e400", "number too large for a double: it is inf"},
                          Case{"val(\"nan\")", "'val' gives nan here"},
                          Case{"<1,1e308,1>*10", "'*' overflows to a vector with inf here"}}) {
        messages.clear();
        EXPECT_FALSE(all_finite(value(c.expr))) << c.expr;
        ASSERT_EQ(messages.size(), 1u) << c.expr;
        EXPECT_EQ(messages[0].message, c.message) << c.expr;
        EXPECT_EQ(messages[0].severity, Severity::Warning);
    }
    // Once announced, an inf travelling on is not reported again.
    messages.clear();
    value("exp(1000) + 1");
    EXPECT_EQ(messages.size(), 1u);
}

// In a function body (POV's function VM) nothing is checked or reported: IEEE results.
TEST_F(MathDomainTest, FunctionBodiesFollowPovRaysVirtualMachine) {
    run("#declare F = function(a) { sqrt(a) }\n"
        "#declare G = function(a) { -1 / a }\n"
        "#declare H = function(a) { acos(a) }\n"
        "#declare L = function(a) { ln(a) }\n");
    EXPECT_TRUE(std::isnan(number("F(-1)")));
    EXPECT_EQ(number("G(0)"), -HUGE_VAL);
    EXPECT_TRUE(std::isnan(number("H(2)")));
    EXPECT_EQ(number("L(0)"), -HUGE_VAL);
    EXPECT_TRUE(messages.empty());
}

}  // namespace
}  // namespace lumen::interp::testing
