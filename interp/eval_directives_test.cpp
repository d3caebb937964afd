// Directives and scoping. The #switch fall-through, #for end test and #declare/#local rules
// were checked against POV-Ray 3.7.
#include "interp/eval_test_support.hpp"

namespace lumen::interp::testing {
namespace {

using DirectiveTest = EvalTest;

TEST_F(DirectiveTest, VersionSetsTheLanguageVersion) {
    run("#version 3.7;");
    EXPECT_DOUBLE_EQ(evaluator().ctx.language_version, 3.7);
    EXPECT_TRUE(evaluator().ctx.version_given);
    EXPECT_DOUBLE_EQ(number("version"), 3.7);
}

TEST_F(DirectiveTest, DeclareLocalAndUndef) {
    run("#declare A = 1;\n#local B = 2;\n#declare C = A + B;\n#undef A\n");
    EXPECT_DOUBLE_EQ(num_var("C"), 3);
    EXPECT_DOUBLE_EQ(num_var("B"), 2);  // #local in the main file is global
    EXPECT_DOUBLE_EQ(number("defined(A)"), 0);
}

TEST_F(DirectiveTest, IfElseifElse) {
    run("#declare V = 2;\n"
        "#if (V = 1) #declare R = 10; #elseif (V = 2) #declare R = 20; #else #declare R = 30; #end\n"
        "#if (0) #declare S = 1; #else #declare S = 2; #end\n"
        "#if (1e-11) #declare T = 1; #else #declare T = 0; #end\n");
    EXPECT_DOUBLE_EQ(num_var("R"), 20);
    EXPECT_DOUBLE_EQ(num_var("S"), 2);
    EXPECT_DOUBLE_EQ(num_var("T"), 0);
}

TEST_F(DirectiveTest, IfdefAndIfndef) {
    run("#declare A = 1;\n#declare Ar = array[3];\n#declare Ar[1] = 5;\n"
        "#ifdef (A) #declare R1 = 1; #else #declare R1 = 0; #end\n"
        "#ifndef (Nope) #declare R2 = 1; #end\n"
        "#ifdef (Ar[1]) #declare R3 = 1; #end\n"
        "#ifndef (Ar[0]) #declare R4 = 1; #end\n");
    EXPECT_DOUBLE_EQ(num_var("R1"), 1);
    EXPECT_DOUBLE_EQ(num_var("R2"), 1);
    EXPECT_DOUBLE_EQ(num_var("R3"), 1);
    EXPECT_DOUBLE_EQ(num_var("R4"), 1);
}

TEST_F(DirectiveTest, SwitchFallsThroughUntilBreak) {
    run("#declare Log = \"\";\n"
        "#switch (3)\n"
        " #case (1) #declare Log = concat(Log, \"one \");\n"
        " #range (2,4) #declare Log = concat(Log, \"range \");\n"
        " #case (5) #declare Log = concat(Log, \"five \"); #break\n"
        " #else #declare Log = concat(Log, \"else\");\n"
        "#end\n"
        "#switch (7) #case (1) #declare Log = concat(Log, \"1\"); #else #declare Log = concat(Log, \"else7\"); #end\n");
    EXPECT_EQ(str("Log"), "range five else7");
}

TEST_F(DirectiveTest, BreakInsideSwitchInsideLoopOnlyLeavesTheSwitch) {
    run("#declare I = 0; #declare N = 0;\n"
        "#while (I < 3) #declare I = I + 1;\n"
        "  #switch (I) #case (1) #break #else #declare N = N + 1; #end\n"
        "#end\n");
    EXPECT_DOUBLE_EQ(num_var("N"), 2);
}

TEST_F(DirectiveTest, WhileAndBreak) {
    run("#declare I = 0;\n#while (I < 10) #declare I = I + 1; #if (I = 4) #break #end #end\n");
    EXPECT_DOUBLE_EQ(num_var("I"), 4);
}

TEST_F(DirectiveTest, ForLoops) {
    run("#declare N = 0; #for (I, 0, 1, 0.1) #declare N = N + 1; #end\n"
        "#declare N2 = 0; #for (J, 0, 0.3, 0.1) #declare N2 = N2 + 1; #end\n"
        "#declare L = \"\"; #for (K, 5, 1, -2) #declare L = concat(L, str(K,0,0)); #end\n"
        "#for (E, 1, 0) #declare Never = 1; #end\n"
        "#declare N3 = 0; #for (M, 0, 10) #declare N3 = N3 + 1; #declare M = M + 1; #end\n");
    EXPECT_DOUBLE_EQ(num_var("N"), 11);
    EXPECT_NEAR(num_var("I"), 1.1, 1e-12);  // the variable ends one step past the end
    EXPECT_DOUBLE_EQ(num_var("N2"), 4);      // the end test allows for rounding
    EXPECT_EQ(str("L"), "531");
    EXPECT_DOUBLE_EQ(num_var("E"), 1);
    EXPECT_DOUBLE_EQ(number("defined(Never)"), 0);
    EXPECT_DOUBLE_EQ(num_var("N3"), 6);      // the body may change the loop variable
    EXPECT_DOUBLE_EQ(num_var("M"), 12);
}

TEST_F(DirectiveTest, ForStepZeroIsAnError) {
    EXPECT_EQ(error_of("#for (I, 0, 1, 0) #end"), "test.pov:1:16: error: #for step must not be 0");
}

TEST_F(DirectiveTest, LoopLimitsGiveErrors) {
    options.max_loop_iterations = 1000;
    EXPECT_EQ(error_of("#while (1)\n#end"), "test.pov:1:1: error: #while loop exceeded 1000 iterations "
                                           "(limit Max_Loop_Iterations): an endless loop?");
    EXPECT_EQ(error_of("#for (I, 0, 1e9) #end"), "test.pov:1:1: error: #for loop exceeded 1000 iterations "
                                                "(limit Max_Loop_Iterations): an endless loop?");
}

TEST_F(DirectiveTest, BreakOutsideALoopIsAnError) {
    EXPECT_EQ(error_of("#declare A = 1;\n  #break"),
              "test.pov:2:3: error: #break outside #switch, #while, #for or a macro");
}

TEST_F(DirectiveTest, DebugAndWarningGoToTheSink) {
    run("#debug \"hello\\n\"\n#warning \"careful\"\n");
    ASSERT_EQ(messages.size(), 2u);
    EXPECT_EQ(messages[0].severity, Severity::Note);
    EXPECT_EQ(messages[0].message, "hello\n");
    EXPECT_EQ(messages[1].severity, Severity::Warning);
    EXPECT_EQ(messages[1].message, "careful");
    EXPECT_EQ(messages[1].loc.line, 2u);
}

TEST_F(DirectiveTest, ErrorDirectiveStopsWithItsText) {
    EXPECT_EQ(error_of("#declare A = 1;\n#error concat(\"bad \", str(A,0,0))\n"), "test.pov:2:1: error: bad 1");
}

TEST_F(DirectiveTest, UndefOfUnknownNameWarns) {
    run("#undef Nothing\n");
    ASSERT_EQ(messages.size(), 1u);
    EXPECT_EQ(messages[0].severity, Severity::Warning);
}

TEST_F(DirectiveTest, ArrayElementAssignmentIsBoundsChecked) {
    EXPECT_EQ(error_of("#declare A = array[2];\n#declare A[2] = 1;"),
              "test.pov:2:12: error: array index 2 is out of range 0..1");
}

TEST_F(DirectiveTest, DirectivesInsideExpressionsOfABlockBody) {
    // Directives may sit between items: the items they produce are spliced in place.
    auto items = run("#declare N = 3;\n#if (N > 2) 1, 2 #else 3 #end 4\n");
    ASSERT_EQ(items.size(), 4u);  // 1 , 2 4
    EXPECT_EQ(items[1].kind, Item::Kind::Comma);
    EXPECT_DOUBLE_EQ(to_float(items[3].value), 4);
}

}  // namespace
}  // namespace lumen::interp::testing
