// Expressions: arithmetic, precedence, promotion, members, colours, arrays, and their errors.
// Expected values were checked with POV-Ray 3.7 (#debug output).
#include "interp/eval_test_support.hpp"

namespace lumen::interp::testing {
namespace {

using ExpressionTest = EvalTest;
using V = std::vector<double>;

TEST_F(ExpressionTest, FloatArithmeticAndPrecedence) {
    EXPECT_DOUBLE_EQ(number("1+2*3-4/2"), 5);
    EXPECT_DOUBLE_EQ(number("10 - 2 - 3"), 5);  // left associative
    EXPECT_DOUBLE_EQ(number("-2 * -3"), 6);
    EXPECT_DOUBLE_EQ(number("(1+2)*3"), 9);
    EXPECT_DOUBLE_EQ(number("2 * 3 + 4 * 5 > 25 & 1"), 1);
    EXPECT_DOUBLE_EQ(number("-2 + 3 < 2"), 1);
    EXPECT_NEAR(number("1/3*3"), 1, 1e-15);
}

// The parser folds long literal sums (BuildState::kFoldedChain); an identifier at the head
// stops it. Both give the interpreter's left-to-right result, bit for bit.
TEST_F(ExpressionTest, FoldedLiteralChainsEvaluateAsWritten) {
    std::string terms;
    for (int i = 1; i <= 40; ++i) terms += " + " + std::to_string(i) + " * 0.1 - 0.3 / 7";
    run("#declare Z = 0;\n#declare A = 0" + terms + ";\n#declare B = Z" + terms + ";\n");
    EXPECT_EQ(num_var("A"), num_var("B"));
    double expect = 0;
    for (int i = 1; i <= 40; ++i) expect = expect + i * 0.1 - 0.3 / 7;
    EXPECT_EQ(num_var("A"), expect);
}

TEST_F(ExpressionTest, ComparisonsUseEpsilon) {
    EXPECT_DOUBLE_EQ(number("3 = 3"), 1);
    EXPECT_DOUBLE_EQ(number("3 != 3"), 0);
    EXPECT_DOUBLE_EQ(number("1e-11 = 0"), 1);  // POV compares within EPSILON = 1e-10
    EXPECT_DOUBLE_EQ(number("1 = 1 + 1e-12"), 1);
    EXPECT_DOUBLE_EQ(number("(1 < 2) + (2 <= 2) + (3 >= 4) + (1 != 1)"), 2);
    EXPECT_DOUBLE_EQ(number("2 > 1"), 1);
}

TEST_F(ExpressionTest, LogicAndTruth) {
    EXPECT_DOUBLE_EQ(number("1 & 0"), 0);
    EXPECT_DOUBLE_EQ(number("0 | 2"), 1);
    EXPECT_DOUBLE_EQ(number("!0"), 1);
    EXPECT_DOUBLE_EQ(number("!2"), 0);
    EXPECT_DOUBLE_EQ(number("1e-11 & 1"), 0);  // |v| <= EPSILON is false
}

TEST_F(ExpressionTest, TernaryChoosesOneBranch) {
    EXPECT_DOUBLE_EQ(number("1 ? 2 : 3"), 2);
    EXPECT_DOUBLE_EQ(number("1e-11 ? 5 : 6"), 6);
    EXPECT_DOUBLE_EQ(number("0 ? Undeclared_Name : 7"), 7);  // the other branch is not evaluated
}

TEST_F(ExpressionTest, VectorPromotion) {
    EXPECT_EQ(vec("<1,2,3> + 1"), (V{2, 3, 4}));
    EXPECT_EQ(vec("2 * <1,2,3>"), (V{2, 4, 6}));
    EXPECT_EQ(vec("<1,2> + 1"), (V{2, 3}));
    EXPECT_EQ(vec("<1,2> + <1,2,3>"), (V{2, 4, 3}));  // the shorter one is padded with 0
    EXPECT_EQ(vec("<1,2,3,4> * 2"), (V{2, 4, 6, 8}));
    EXPECT_EQ(vec("<1,2,3> * <2,2,2>"), (V{2, 4, 6}));
    EXPECT_EQ(vec("-<1,2,3>"), (V{-1, -2, -3}));
    EXPECT_EQ(vec("x + 2*y - z"), (V{1, 2, -1}));
    EXPECT_EQ(vec("<1,2,3> / 2"), (V{0.5, 1, 1.5}));
}

TEST_F(ExpressionTest, ColourPromotion) {
    EXPECT_EQ(vec("rgb <1,0.5,0> * 2"), (V{2, 1, 0, 0, 0}));
    EXPECT_EQ(vec("rgb 1 + 1"), (V{2, 2, 2, 0, 0}));
    run("#declare C = rgb 1;");
    EXPECT_EQ(vec("C + 1"), (V{2, 2, 2, 1, 1}));  // a float fills all five channels
    EXPECT_EQ(vec("C + <1,2,3>"), (V{2, 3, 4, 0, 0}));
    EXPECT_TRUE(value("C * 0.5").is<scene::Colour>());
}

TEST_F(ExpressionTest, ColourSyntax) {
    EXPECT_EQ(vec("color <1,2,3>"), (V{1, 2, 3, 0, 0}));
    EXPECT_EQ(vec("color <1,2,3,4>"), (V{1, 2, 3, 4, 0}));
    EXPECT_EQ(vec("color 0.5"), (V{0.5, 0.5, 0.5, 0.5, 0.5}));  // see-through, as POV
    EXPECT_EQ(vec("rgb 0.5"), (V{0.5, 0.5, 0.5, 0, 0}));
    EXPECT_EQ(vec("rgbf 0.5"), (V{0.5, 0.5, 0.5, 0.5, 0}));
    EXPECT_EQ(vec("rgbt <1,2,3,4>"), (V{1, 2, 3, 0, 4}));
    EXPECT_EQ(vec("rgbft <1,2,3,4,5>"), (V{1, 2, 3, 4, 5}));
    EXPECT_EQ(vec("color rgbf 0.5 transmit 0.1"), (V{0.5, 0.5, 0.5, 0.5, 0.1}));
    EXPECT_EQ(vec("rgb 1 filter 0.3 red 0.1"), (V{0.1, 1, 1, 0.3, 0}));
    EXPECT_EQ(vec("color red 1 green 0.5"), (V{1, 0.5, 0, 0, 0}));
    run("#declare R = rgbft <1,0,0,0.2,0.2>;");
    EXPECT_EQ(vec("color R filter 0.5"), (V{1, 0, 0, 0.5, 0.2}));
    EXPECT_EQ(vec("color rgb R"), (V{1, 0, 0, 0.2, 0.2}));  // rgb of a colour keeps it whole
    EXPECT_EQ(vec("rgb x"), (V{1, 0, 0, 0, 0}));
    std::vector<double> s = vec("srgb 0.5");
    EXPECT_NEAR(s[0], 0.214041, 1e-6);
    EXPECT_EQ(s[3], 0);
}

TEST_F(ExpressionTest, Members) {
    EXPECT_DOUBLE_EQ(number("<1,2,3>.y"), 2);
    EXPECT_DOUBLE_EQ(number("<1,2,3>.x + <1,2,3>.z"), 4);
    EXPECT_DOUBLE_EQ(number("<1,2,3,4>.t"), 4);
    EXPECT_DOUBLE_EQ(number("<5,6>.v"), 6);
    run("#declare C = rgbft <0.2,0.4,0.6,0.7,0.8>;");
    EXPECT_NEAR(number("C.gray"), 0.3634, 1e-12);
    EXPECT_DOUBLE_EQ(number("C.red"), 0.2);
    EXPECT_DOUBLE_EQ(number("C.green"), 0.4);
    EXPECT_DOUBLE_EQ(number("C.blue"), 0.6);
    EXPECT_DOUBLE_EQ(number("C.filter"), 0.7);
    EXPECT_DOUBLE_EQ(number("C.transmit"), 0.8);
    EXPECT_EQ(expr_error("<5,6>.z"), "expr:1:1: error: a 2-component vector has no component '.z'");
}

TEST_F(ExpressionTest, Strings) {
    EXPECT_EQ(str("\"abc\""), "abc");
    run("#declare S = \"abc\";");
    EXPECT_DOUBLE_EQ(number("S != \"\""), 1);  // strings compare like strcmp (POV-Ray 3.7)
    EXPECT_DOUBLE_EQ(number("S = \"abc\""), 1);
    EXPECT_DOUBLE_EQ(number("S < \"abd\""), 1);
    EXPECT_DOUBLE_EQ(number("\"b\" > \"a\""), 1);
    EXPECT_DOUBLE_EQ(number("\"b\" <= \"a\""), 0);
    EXPECT_EQ(expr_error("\"a\" + 1"), "expr:1:1: error: expected a float, vector or colour, found a string");
}

TEST_F(ExpressionTest, Arrays) {
    run("#declare A = array[2][3] {{1,2,3},{4,5,6}};\n"
        "#declare B = array[3];\n"
        "#declare B[1] = <1,2,3>;\n"
        "#declare I = 1;\n");
    EXPECT_DOUBLE_EQ(number("A[1][2]"), 6);
    EXPECT_DOUBLE_EQ(number("A[0][I+1]"), 3);
    EXPECT_EQ(vec("B[1]"), (V{1, 2, 3}));
    EXPECT_EQ(expr_error("B[0]"), "expr:1:1: error: array element used before it was initialised");
    EXPECT_EQ(expr_error("B[3]"), "expr:1:3: error: array index 3 is out of range 0..2");
    EXPECT_EQ(expr_error("A[-1][0]"), "expr:1:3: error: array index -1 is out of range 0..1");
    EXPECT_EQ(expr_error("A[1]"), "expr:1:1: error: array has 2 dimension(s) but 1 index(es) were given");
}

TEST_F(ExpressionTest, ArrayAssignmentCopies) {
    run("#declare A = array[2] {1, 2};\n"
        "#declare B = A;\n"
        "#declare B[0] = 10;\n");
    EXPECT_DOUBLE_EQ(number("A[0]"), 1);
    EXPECT_DOUBLE_EQ(number("B[0]"), 10);
}

TEST_F(ExpressionTest, ArrayInitialiserSizeMustMatch) {
    EXPECT_EQ(error_of("#declare A = array[3] {1, 2};"),
              "test.pov:1:23: error: array initialiser has 2 elements, expected 3");
}

TEST_F(ExpressionTest, DivisionByZeroWarnsAndDoesNotCrash) {
    EXPECT_TRUE(std::isinf(number("1/0")));
    ASSERT_FALSE(messages.empty());
    EXPECT_EQ(messages[0].message, "division by zero gives inf");
}

TEST_F(ExpressionTest, UndeclaredIdentifierSuggestsAName) {
    run("#declare Radius = 1;");
    try {
        value("Radiux * 2");
        FAIL() << "expected an error";
    } catch (const LumenError& e) {
        EXPECT_EQ(e.diag.message, "undeclared identifier 'Radiux'");
        EXPECT_EQ(e.diag.hint, "did you mean 'Radius'?");
        EXPECT_EQ(e.diag.loc.column, 1u);
    }
}

TEST_F(ExpressionTest, TypeErrorsNameBothTypes) {
    run("#declare S = \"text\";");
    EXPECT_EQ(expr_error("<1, S, 3>"), "expr:1:5: error: expected a float, found a string");
    EXPECT_EQ(expr_error("1 < <1,2>"), "expr:1:5: error: expected a float, found a vector");
}

TEST_F(ExpressionTest, BuiltinConstants) {
    EXPECT_DOUBLE_EQ(number("pi"), 3.14159265358979323846);
    EXPECT_DOUBLE_EQ(number("true + yes + on"), 3);
    EXPECT_DOUBLE_EQ(number("false + no + off"), 0);
    EXPECT_EQ(vec("t"), (V{0, 0, 0, 1}));
    EXPECT_EQ(vec("u + v"), (V{1, 1}));
    EXPECT_DOUBLE_EQ(number("version"), 3.7);  // no #version: reads 3.7 (the scene is 3.62)
    EXPECT_DOUBLE_EQ(number("image_width"), 320);
    EXPECT_DOUBLE_EQ(number("image_height"), 240);
}

TEST_F(ExpressionTest, AnimationConstantsFollowTheOptions) {
    options.clock = 0.1;
    options.clock_delta = 1.0 / 3.0;
    options.frame_number = 4;
    options.clock_on = true;
    EXPECT_DOUBLE_EQ(number("clock"), static_cast<double>(0.1f));  // a 32-bit float
    EXPECT_DOUBLE_EQ(number("clock_delta"), 0.333333);
    EXPECT_DOUBLE_EQ(number("frame_number"), 4);
    EXPECT_DOUBLE_EQ(number("clock_on"), 1);
    EXPECT_DOUBLE_EQ(number("initial_frame + final_frame"), 2);
    EXPECT_DOUBLE_EQ(number("initial_clock + final_clock"), 1);
}

}  // namespace
}  // namespace lumen::interp::testing
