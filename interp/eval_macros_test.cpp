// Macros and POV-Ray's dynamic scoping (checked against POV-Ray 3.7).
#include "interp/eval_test_support.hpp"

namespace lumen::interp::testing {
namespace {

using MacroTest = EvalTest;

TEST_F(MacroTest, RecursiveFactorial) {
    run("#macro Fact(N) #if (N <= 1) 1 #else N * Fact(N - 1) #end #end\n"
        "#declare F5 = Fact(5);\n");
    EXPECT_DOUBLE_EQ(num_var("F5"), 120);
    EXPECT_DOUBLE_EQ(number("Fact(6) + 1"), 721);
}

TEST_F(MacroTest, MacroInAnExpressionMustGiveOneValue) {
    run("#macro Two() 1, 2 #end\n#macro None() #end\n");
    EXPECT_EQ(expr_error("Two() + 1"), "expr:1:1: error: macro 'Two' used in an expression produced 3 items");
    EXPECT_EQ(expr_error("None()"), "expr:1:1: error: macro 'None' used in an expression produced 0 items");
}

TEST_F(MacroTest, MacroAtItemLevelSplicesItsItems) {
    auto items = run("#macro Pair(A, B) A, B #end\nPair(1, <2,3,4>) 5\n");
    ASSERT_EQ(items.size(), 4u);
    EXPECT_DOUBLE_EQ(to_float(items[0].value), 1);
    EXPECT_EQ(items[1].kind, Item::Kind::Comma);
    EXPECT_EQ(components(items[2].value), (std::vector<double>{2, 3, 4}));
    EXPECT_DOUBLE_EQ(to_float(items[3].value), 5);
}

TEST_F(MacroTest, AnObjectArgumentEndsWhereItsObjectEnds) {
    // POV-Ray (shapes.inc's callers, incdemo/shapes.pov): `Obj -y` with no comma is Obj, then -y.
    run("#macro Three(O, V, N) #declare Got = V; #declare GotN = N; #end\n"
        "#macro Ball() sphere { 0, 1 } #end\n"
        "Three(Ball() -y + x, 4)\n"
        "#declare Sum = 0; #macro Two(A, B) #declare Sum = A + B; #end Two(1 - 2, 5)\n");
    EXPECT_EQ(components(var("Got")), (std::vector<double>{1, -1, 0}));
    EXPECT_DOUBLE_EQ(num_var("GotN"), 4);
    EXPECT_DOUBLE_EQ(num_var("Sum"), 4);  // a numeric argument is one expression
}

// shapes.inc's HFCreate_ opens a #write( or a mesh2 { in one #if branch and closes it in a
// later #if: the body has a tree only once its conditions are decided at the call.
TEST_F(MacroTest, ABodyOpenedAndClosedAcrossConditionalsRunsAsPovRayReadsIt) {
    run("#macro Op(Add)\n"
        "  #declare R = #if (Add) 2 + #else 2 * #end 5;\n"
        "  #declare L = array[2] { #if (Add) 1, #else 3, #end 4 #if (Add) } #else } #end\n"
        "#end\n"
        "Op(1) #declare Sum = R; #declare First = L[0];\n"
        "Op(0) #declare Product = R; #declare FirstOfOther = L[0];\n"
        "Op(yes) #declare Again = R;\n");
    EXPECT_DOUBLE_EQ(num_var("Sum"), 7);
    EXPECT_DOUBLE_EQ(num_var("First"), 1);
    EXPECT_DOUBLE_EQ(num_var("Product"), 10);
    EXPECT_DOUBLE_EQ(num_var("Again"), 7);
    EXPECT_DOUBLE_EQ(num_var("FirstOfOther"), 3);
}

TEST_F(MacroTest, ConditionsTheBodyAssignsAreNotDecidedEarly) {
    // W changes inside the body, so deciding it at the call could differ from running it:
    // the body's own syntax error stands, at its place.
    EXPECT_EQ(error_of("#macro Bad()\n  #local W = 1;\n  #declare R = #if (W) 2 + #else 2 * #end 5;\n#end\nBad()\n"),
              "test.pov:3:29: error: expected expression after operator, found 'else'");
    // Nor a condition that draws a random number: the stream would advance once, not per run.
    EXPECT_EQ(error_of("#declare S = seed(1);\n#macro Bad()\n  #declare R = #if (rand(S) < 2) 2 + #else 2 * #end 5;\n#end\nBad()\n"),
              "test.pov:3:39: error: expected expression after operator, found 'else'");
    // An error inside a decided body keeps its line and column.
    EXPECT_EQ(error_of("#macro Op(Add)\n  #declare R = #if (Add) 2 + #else 2 * #end\n    Nope;\n#end\nOp(1)\n"),
              "test.pov:3:5: error: undeclared identifier 'Nope'");
}

TEST_F(MacroTest, ParametersAreLocal) {
    run("#declare P = 100;\n#macro M(P) #declare Seen = P; #end\nM(7)\n");
    EXPECT_DOUBLE_EQ(num_var("Seen"), 7);
    EXPECT_DOUBLE_EQ(num_var("P"), 100);
}

TEST_F(MacroTest, IdentifierArgumentsArePassedByReference) {
    run("#macro AddTen(P) #declare P = P + 10; #end\n"
        "#macro SetLocal(P) #local P = 99; #end\n"
        "#declare A = 1; AddTen(A)\n"
        "#declare B = 2; SetLocal(B)\n"
        "#declare C = 3; AddTen(C + 0)\n");
    EXPECT_DOUBLE_EQ(num_var("A"), 11);
    EXPECT_DOUBLE_EQ(num_var("B"), 99);  // POV copies back even a #local
    EXPECT_DOUBLE_EQ(num_var("C"), 3);   // an expression is passed by value
}

TEST_F(MacroTest, DeclareUpdatesTheInnermostExistingBinding) {
    run("#declare G = 1;\n"
        "#macro M() #local G = 5; #declare G = 7; #declare Inside = G; #declare NewOne = 3; #end\n"
        "M()\n");
    EXPECT_DOUBLE_EQ(num_var("Inside"), 7);
    EXPECT_DOUBLE_EQ(num_var("G"), 1);       // the global was not touched
    EXPECT_DOUBLE_EQ(num_var("NewOne"), 3);  // a new #declare is global
}

TEST_F(MacroTest, ScopingIsDynamic) {
    run("#macro Q() #local L = 4; R() #declare AfterR = L; #end\n"
        "#macro R() #declare Seen = L; #declare L = 8; #end\n"
        "Q()\n");
    EXPECT_DOUBLE_EQ(num_var("Seen"), 4);    // R sees its caller's local
    EXPECT_DOUBLE_EQ(num_var("AfterR"), 8);  // and #declare changed that local
    EXPECT_DOUBLE_EQ(number("defined(L)"), 0);
}

TEST_F(MacroTest, ForVariableInsideAMacroIsLocal) {
    run("#macro M() #for (Q, 1, 2) #end #end\nM()\n");
    EXPECT_DOUBLE_EQ(number("defined(Q)"), 0);
}

TEST_F(MacroTest, OptionalParameters) {
    run("#macro M(A, optional B) #ifdef (B) A + B #else A #end #end\n");
    EXPECT_DOUBLE_EQ(number("M(1, 2)"), 3);
    EXPECT_DOUBLE_EQ(number("M(1)"), 1);
}

TEST_F(MacroTest, ArgumentCountErrors) {
    run("#macro M(A, B) A #end\n");
    EXPECT_EQ(expr_error("M(1)"), "expr:1:1: error: macro 'M' needs a value for parameter 'B'");
    EXPECT_EQ(expr_error("M(1, 2, 3)"), "expr:1:1: error: macro 'M' expects 2 argument(s), found 3");
}

TEST_F(MacroTest, MacroNameWithoutArgumentsIsAnError) {
    run("#macro M() 1 #end\n");
    EXPECT_EQ(expr_error("M + 1"), "expr:1:1: error: macro 'M' must be called with an argument list: M(...)");
}

TEST_F(MacroTest, BreakEndsTheMacroOnly) {
    run("#declare Log = \"\";\n"
        "#macro Mb() #declare Log = concat(Log, \"m1 \"); #break #declare Log = concat(Log, \"m2 \"); #end\n"
        "#switch (1) #case (1) Mb() #declare Log = concat(Log, \"after\"); #end\n");
    EXPECT_EQ(str("Log"), "m1 after");
}

TEST_F(MacroTest, RecursionDepthIsLimited) {
    options.max_macro_depth = 50;
    EXPECT_EQ(error_of("#macro Forever(N) Forever(N + 1) #end\nForever(0)\n"),
              "test.pov:1:19: error: macro 'Forever' nested more than 50 calls deep");
}

TEST_F(MacroTest, DeepRecursionWithinTheDefaultLimitRuns) {
    run("#macro Count(N) #if (N > 0) Count(N - 1) + 1 #else 0 #end #end\n#declare D = Count(150);\n");
    EXPECT_DOUBLE_EQ(num_var("D"), 150);
}

TEST_F(MacroTest, ErrorsInsideAMacroPointIntoItsBody) {
    EXPECT_EQ(error_of("#macro M()\n  Undefined_Thing\n#end\nM()\n"),
              "test.pov:2:3: error: undeclared identifier 'Undefined_Thing'");
}

}  // namespace
}  // namespace lumen::interp::testing
