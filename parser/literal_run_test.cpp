// Literal runs (grammar.hpp's literal_run): long lists of floats and vectors in a block body
// are kept as one array node, and only where nothing could join an element to an expression.
#include <gtest/gtest.h>

#include "parser/test_util.hpp"

namespace lumen::parser {
namespace {

using testing::expr;
using testing::items;

TEST(LiteralRun, LongListsOfFloatsAndVectorsBecomeOneNode) {
    EXPECT_EQ(items("vertex_vectors { 7, <0,0,0>, <1,-2.5,3e2>, <.5, 5.,-0> <1,2> <1,2,3,4,5>,\n"
                    "  // a comment\n  /* and another */ <7,8,9,>, 6 }"),
              "(Block vertex_vectors (Literals 7 , <0 0 0> , <1 -2.5 300> , <0.5 5 -0> <1 2> "
              "<1 2 3 4 5> , <7 8 9> , 6))");
}

TEST(LiteralRun, ShortListsStayNodes) {
    // Seven floats and vectors: below kMinLiteralRun.
    EXPECT_EQ(items("polygon { 3, <0,0>, <1,0>, <0,1>, 1, 2, 3 }"),
              "(Block polygon (Number 3) (Comma) (Vector (Number 0) (Number 0)) (Comma) "
              "(Vector (Number 1) (Number 0)) (Comma) (Vector (Number 0) (Number 1)) (Comma) "
              "(Number 1) (Comma) (Number 2) (Comma) (Number 3))");
}

TEST(LiteralRun, AnOperatorAfterAnElementEndsTheRun) {
    // `9 - 1` and `<1,1> * 2` are expressions: the run stops before them, and they keep their
    // meaning (a space-separated sign is subtraction, as in POV-Ray).
    EXPECT_EQ(items("b { 1,2,3,4,5,6,7,8, 9 - 1 }"),
              "(Block b (Literals 1 , 2 , 3 , 4 , 5 , 6 , 7 , 8 ,) "
              "(Binary (Number 9) - (Number 1)))");
    EXPECT_EQ(items("b { 1,2,3,4,5,6,7,8 <1,1> * 2 }"),
              "(Block b (Literals 1 , 2 , 3 , 4 , 5 , 6 , 7 , 8) "
              "(Binary (Vector (Number 1) (Number 1)) * (Number 2)))");
    // A component that an operator follows makes the whole vector an ordinary one.
    EXPECT_EQ(items("b { <1 -2, 3>, 1,2,3,4,5,6,7,8 }"),
              "(Block b (Vector (Binary (Number 1) - (Number 2)) (Number 3)) "
              "(Literals , 1 , 2 , 3 , 4 , 5 , 6 , 7 , 8))");
}

TEST(LiteralRun, WhatTheRunCannotHoldIsReadAsBefore) {
    // An overflowing float (the interpreter warns where it is written), a one-component and a
    // six-component vector (errors there) and identifiers stay nodes.
    EXPECT_EQ(items("b { 1e999, 1,2,3,4,5,6,7,8 }"),
              "(Block b (Number inf) (Literals , 1 , 2 , 3 , 4 , 5 , 6 , 7 , 8))");
    EXPECT_EQ(items("b { <1>, 1,2,3,4,5,6,7,8 }"),
              "(Block b (Vector (Number 1)) (Literals , 1 , 2 , 3 , 4 , 5 , 6 , 7 , 8))");
    EXPECT_EQ(items("b { 1,2,3,4,5,6,7,8, <1,2,3,4,5,6> }"),
              "(Block b (Literals 1 , 2 , 3 , 4 , 5 , 6 , 7 , 8 ,) (Vector (Number 1) (Number 2) "
              "(Number 3) (Number 4) (Number 5) (Number 6)))");
    EXPECT_EQ(items("b { 1,2,3,4,5,6,7,8, x }"),
              "(Block b (Literals 1 , 2 , 3 , 4 , 5 , 6 , 7 , 8 ,) (Ident x))");
}

TEST(LiteralRun, ElementsKeepTheirOwnLocations) {
    const testing::Parsed p = testing::parse_text("b {\n 1, 2,\t3, 4,\n  5, 6, 7, <8, 9>\n}");
    const ast::Node& run = *p.root->children.at(0)->children.at(0);
    ASSERT_EQ(run.kind, ast::Kind::Literals);
    const ast::LiteralRun& r = *run.more().literals;
    auto at = [&](size_t i) {
        const SourceLoc l = r.loc(p.file.get(), i);
        return std::to_string(l.line) + ":" + std::to_string(l.column);
    };
    EXPECT_EQ(at(0), "2:2");   // 1
    EXPECT_EQ(at(4), "2:8");   // 3 (a tab is one byte)
    EXPECT_EQ(at(8), "3:3");   // 5
    EXPECT_EQ(at(14), "3:12");  // <8, 9>
    EXPECT_EQ(r.value_elements, 8u);
}

// Long sums and products of literals fold while they are read (BuildState::kFoldedChain).
TEST(LiteralChain, LongLiteralSumsFoldShortOnesDoNot) {
    std::string terms = "1";
    for (int i = 2; i <= 20; ++i) terms += " + " + std::to_string(i) + " * 0.5";
    // 1 + 0.5 * (2 + ... + 19) folded into the head; the last operand is read after the last
    // operator, so it stays.
    EXPECT_EQ(items("#declare S = " + terms + ";"),
              "(Declare declare (Ident S) (Binary (Number 95.5) + (Binary (Number 20) * (Number 0.5))))");
    EXPECT_EQ(expr("1 + 2 * 3"), "(Binary (Number 1) + (Binary (Number 2) * (Number 3)))");
    // An identifier stops the folding where it stands; what follows keeps its nodes.
    std::string mixed = "1";
    for (int i = 2; i <= 18; ++i) mixed += " + " + std::to_string(i);
    EXPECT_EQ(items("#declare S = " + mixed + " + x + 19 + 20;"),
              "(Declare declare (Ident S) (Binary (Number 171) + (Ident x) + (Number 19) + (Number 20)))");
    // Division by zero and overflow are left to the interpreter, which warns about them.
    std::string zero = "1 / 0";
    for (int i = 2; i <= 20; ++i) zero += " + " + std::to_string(i);
    EXPECT_NE(items("#declare S = " + zero + ";").find("(Binary (Number 1) / (Number 0))"),
              std::string::npos);
}

}  // namespace
}  // namespace lumen::parser
