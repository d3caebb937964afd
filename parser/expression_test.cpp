// Expressions: precedence, flat operator chains, vectors versus comparisons, colours, calls.
#include <gtest/gtest.h>

#include "parser/test_util.hpp"

namespace lumen::parser {
namespace {

using testing::expr;
using testing::items;

TEST(Expression, NumberForms) {
    EXPECT_EQ(expr("1"), "(Number 1)");
    EXPECT_EQ(expr("1.5"), "(Number 1.5)");
    EXPECT_EQ(expr(".5"), "(Number 0.5)");
    EXPECT_EQ(expr("1e-3"), "(Number 0.001)");
    EXPECT_EQ(expr("1."), "(Number 1)");
    EXPECT_EQ(expr("2.5E+2"), "(Number 250)");
}

TEST(Expression, StringEscapes) {
    EXPECT_EQ(expr(R"("a\"b\\c\n")"), "(String \"a\"b\\c\n\")");
    EXPECT_EQ(expr(R"("C:\path")"), "(String \"C:\\path\")");  // unknown escape kept
}

TEST(Expression, PrecedenceMulOverAdd) {
    EXPECT_EQ(expr("1+2*3"), "(Binary (Number 1) + (Binary (Number 2) * (Number 3)))");
    EXPECT_EQ(expr("(1+2)*3"), "(Binary (Binary (Number 1) + (Number 2)) * (Number 3))");
}

TEST(Expression, ChainsAreFlat) {
    EXPECT_EQ(expr("1-2-3+4"), "(Binary (Number 1) - (Number 2) - (Number 3) + (Number 4))");
    EXPECT_EQ(expr("a*b/c"), "(Binary (Ident a) * (Ident b) / (Ident c))");
}

TEST(Expression, ComparisonAndLogicInParentheses) {
    EXPECT_EQ(expr("(a < b & c >= 2 | !d)"),
              "(Binary (Binary (Binary (Ident a) < (Ident b)) & (Binary (Ident c) >= (Number 2)))"
              " | (Unary ! (Ident d)))");
    EXPECT_EQ(expr("(a = 1)"), "(Binary (Ident a) = (Number 1))");
    EXPECT_EQ(expr("(a != 1)"), "(Binary (Ident a) != (Number 1))");
}

TEST(Expression, TernaryIsLowest) {
    EXPECT_EQ(expr("(a > 0) ? 1 + 1 : 2"),
              "(Ternary (Binary (Ident a) > (Number 0)) (Binary (Number 1) + (Number 1)) (Number 2))");
    EXPECT_EQ(expr("a ? b : c ? d : e"),
              "(Ternary (Ident a) (Ident b) (Ternary (Ident c) (Ident d) (Ident e)))");
}

TEST(Expression, UnaryBindsTighterThanBinary) {
    EXPECT_EQ(expr("-a*b"), "(Binary (Unary - (Ident a)) * (Ident b))");
    EXPECT_EQ(expr("- -1"), "(Unary - (Unary - (Number 1)))");
    EXPECT_EQ(expr("+x"), "(Unary + (Ident x))");
}

TEST(Expression, PostfixMemberAndIndex) {
    EXPECT_EQ(expr("V.x"), "(Member x (Ident V))");
    EXPECT_EQ(expr("A[1][i+1]"), "(Index (Ident A) (Number 1) (Binary (Ident i) + (Number 1)))");
    EXPECT_EQ(expr("A[1].red"), "(Member red (Index (Ident A) (Number 1)))");
    EXPECT_EQ(expr("-P(1).y"), "(Unary - (Member y (Call P (Number 1))))");
}

TEST(Expression, VectorLiterals) {
    // A signed number that ends its component is one Number (the value of the unary minus).
    EXPECT_EQ(expr("<1, -2, 3>"), "(Vector (Number 1) (Number -2) (Number 3))");
    EXPECT_EQ(expr("<1, -2 * 3, - 4>"),
              "(Vector (Number 1) (Binary (Unary - (Number 2)) * (Number 3)) (Unary - (Number 4)))");
    EXPECT_EQ(expr("<-1.5e-3,2.>"), "(Vector (Number -0.0015) (Number 2))");
    EXPECT_EQ(expr("<1>"), "(Vector (Number 1))");
    EXPECT_EQ(expr("< -1 0 0 >"), "(Vector (Unary - (Number 1)) (Number 0) (Number 0))");
    EXPECT_EQ(expr("<1,2,3,>"), "(Vector (Number 1) (Number 2) (Number 3))");
    EXPECT_EQ(expr("<1,2>*2"), "(Binary (Vector (Number 1) (Number 2)) * (Number 2))");
}

TEST(Expression, GreaterThanClosesVectorButParenthesesRestoreIt) {
    EXPECT_EQ(expr("<(a > b), 1>"), "(Vector (Binary (Ident a) > (Ident b)) (Number 1))");
    EXPECT_EQ(expr("<1,2,3,4,5,6,7,8,9,10,11,12>").size(),
              std::string("(Vector").size() + 12 * std::string(" (Number 1)").size() + 3 + 1);
}

TEST(Expression, LessThanAfterOperandStartsNextVector) {
    // POV reads comparisons only inside parentheses: these are two vectors.
    EXPECT_EQ(items("box { <0,0,0> <1,1,1> }"),
              "(Block box (Vector (Number 0) (Number 0) (Number 0))"
              " (Vector (Number 1) (Number 1) (Number 1)))");
    EXPECT_EQ(items("slope_map { [0 <0,1>] }"),
              "(Block slope_map (MapEntry (Number 0) (Vector (Number 0) (Number 1))))");
}

TEST(Expression, Calls) {
    EXPECT_EQ(expr("vrotate(x, <0,90,0>)"),
              "(Call vrotate (Ident x) (Vector (Number 0) (Number 90) (Number 0)))");
    EXPECT_EQ(expr("Foo()"), "(Call Foo)");
    EXPECT_EQ(expr("sin (pi/2)"), "(Call sin (Binary (Ident pi) / (Number 2)))");
    EXPECT_EQ(expr("M(1 2)"), "(Call M (Number 1) (Number 2))");  // commas may be omitted
    EXPECT_EQ(expr("M(texture { T })"), "(Call M (Block texture (Ident T)))");
    EXPECT_EQ(expr("internal(42)"), "(Call internal (Number 42))");
}

TEST(Expression, ConstantsAreIdents) {
    EXPECT_EQ(expr("clock*pi+image_width"),
              "(Binary (Binary (Ident clock) * (Ident pi)) + (Ident image_width))");
    EXPECT_EQ(expr("true"), "(Ident true)");
}

TEST(Expression, ColourExpressions) {
    EXPECT_EQ(expr("color rgb <1,0,0> filter 0.5"),
              "(Colour (ColourPart rgb (Vector (Number 1) (Number 0) (Number 0)))"
              " (ColourPart filter (Number 0.5)))");
    EXPECT_EQ(expr("colour Red"), "(Colour (ColourPart (Ident Red)))");
    EXPECT_EQ(expr("rgbt <1,1,1,0.7>"),
              "(Colour (ColourPart rgbt (Vector (Number 1) (Number 1) (Number 1) (Number 0.7))))");
    EXPECT_EQ(expr("color red 1 green 0.5"),
              "(Colour (ColourPart red (Number 1)) (ColourPart green (Number 0.5)))");
    EXPECT_EQ(expr("color 0.5"), "(Colour (ColourPart (Number 0.5)))");
    EXPECT_EQ(expr("color Red*0.5"),
              "(Colour (ColourPart (Binary (Ident Red) * (Number 0.5))))");
    EXPECT_EQ(expr("rgb 1 * 0.5"),
              "(Colour (ColourPart rgb (Binary (Number 1) * (Number 0.5))))");
    EXPECT_EQ(expr("srgbft <1,1,1,0,0>").substr(0, 26), "(Colour (ColourPart srgbft");
}

TEST(Expression, ComponentWordsOutsideColoursAreKeywords) {
    EXPECT_EQ(items("pigment { Red filter 0.5 }"),
              "(Block pigment (Ident Red) (Keyword filter) (Number 0.5))");
    EXPECT_EQ(items("pigment { color Red filter 0.5 }"),
              "(Block pigment (Colour (ColourPart (Ident Red)) (ColourPart filter (Number 0.5))))");
}

TEST(Expression, ArrayDeclarations) {
    EXPECT_EQ(expr("array[2][3]"), "(ArrayDecl (Number 2) (Number 3))");
    EXPECT_EQ(expr("array[2] {1, 2}"), "(ArrayDecl init (Number 2) (ArrayInit (Number 1) (Number 2)))");
    EXPECT_EQ(expr("array[2][1] {{1}, {2},}"),
              "(ArrayDecl init (Number 2) (Number 1) (ArrayInit (ArrayInit (Number 1))"
              " (ArrayInit (Number 2))))");
    EXPECT_EQ(expr("array[1] {texture { T }}"),
              "(ArrayDecl init (Number 1) (ArrayInit (Block texture (Ident T))))");
}

TEST(Expression, IfInsideExpression) {
    EXPECT_EQ(expr("(#if (M) 1 #else 2 #end)"),
              "(If (Branch (Ident M) (Body (Number 1))) (Branch (Null) (Body (Number 2))))");
}

TEST(Expression, ExpressionEntryRejectsTrailingText) {
    SourceFile f{"expr", "1 + 2 }"};
    EXPECT_THROW(parse_expression(f), LumenError);
}

}  // namespace
}  // namespace lumen::parser
