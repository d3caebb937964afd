// Syntax errors: compiler-like messages at exact locations, and no crash on hostile input.
#include <gtest/gtest.h>

#include "parser/test_util.hpp"

namespace lumen::parser {
namespace {

using testing::error_of;
using testing::expr;

TEST(Errors, UnterminatedStringAndComment) {
    EXPECT_EQ(error_of("sphere { 0, 1 \"abc"), "unterminated string @1:15");
    EXPECT_EQ(error_of("1\n  /* open /* nested */ 1"), "unterminated comment @2:3");
}

TEST(Errors, UnclosedBlockNamesItsOpening) {
    EXPECT_EQ(error_of("\n\nsphere { 0, 1\n"),
              "expected '}' to close 'sphere' block opened at 3:1, found end of file @4:1");
    EXPECT_EQ(error_of("union {\n  box { 0, 1 #else }"),
              "expected '}' to close 'box' block opened at 2:3, found '#else' @2:14");
}

TEST(Errors, MissingParenthesisAndVectorEnd) {
    EXPECT_EQ(error_of("#declare A = (1 + 2;"), "expected ')', found ';' @1:20");
    EXPECT_EQ(error_of("foo(1, 2"), "expected ')', found end of file @1:9");
    EXPECT_EQ(error_of("<1, 2"), "expected '>' to close vector, found end of file @1:6");
    EXPECT_EQ(error_of("a ? b"), "expected ':' in conditional expression, found end of file @1:6");
}

TEST(Errors, DirectiveStructure) {
    EXPECT_EQ(error_of("#end"), "#end without matching directive @1:1");
    EXPECT_EQ(error_of("x\n#else"), "#else without matching #if @2:1");
    EXPECT_EQ(error_of("#switch (1) #case (1) #end #end"), "#end without matching directive @1:28");
    EXPECT_EQ(error_of("\n\n\n#if (1)\n sphere {}\n"), "missing #end for #if at 4:1 @6:1");
    EXPECT_EQ(error_of("#macro M(A)\n sphere{}\n"), "missing #end for #macro at 1:1 @3:1");
    EXPECT_EQ(error_of("#while (1) }"), "expected #end for #while at 1:1 @1:12");
    EXPECT_EQ(error_of("}"), "unmatched '}' @1:1");
}

TEST(Errors, UnknownDirectiveSuggestsTheClosestOne) {
    SourceFile f{"t.pov", "#declre A = 1;"};
    try {
        parse_file(f);
        FAIL() << "no error";
    } catch (const LumenError& e) {
        EXPECT_STREQ(e.what(), "unknown directive '#declre'");
        EXPECT_EQ(e.diag.hint, "did you mean 'declare'?");
        EXPECT_EQ(e.diag.loc.column, 1u);
    }
}

TEST(Errors, DeclaringAReservedWord) {
    EXPECT_EQ(error_of("#declare sphere = 1;"),
              "cannot declare 'sphere': it is a reserved word @1:10");
    EXPECT_EQ(error_of("#local pi = 3;"), "cannot declare 'pi': it is a reserved word @1:8");
    EXPECT_EQ(error_of("#declare A 1;"), "expected '=' after the declared name, found '1' @1:12");
    EXPECT_EQ(error_of("#declare A = ;"), "expected value after '=', found ';' @1:14");
}

TEST(Errors, MapEntriesAndArrays) {
    EXPECT_EQ(error_of("color_map { [0 rgb 1 }"),
              "expected ']' to close map entry opened at 1:13, found '}' @1:22");
    EXPECT_EQ(error_of("#declare A = array[2] {1, 2"),
              "expected '}' to close array initialiser opened at 1:23, found end of file @1:28");
}

TEST(Errors, OperatorWithoutOperand) {
    EXPECT_EQ(error_of("#declare F = function { x + }"),
              "expected expression after operator, found '}' @1:29");
    EXPECT_EQ(error_of("@"), "unexpected '@' @1:1");
}

std::string repeat(const std::string& s, int n) {
    std::string r;
    for (int i = 0; i < n; ++i) r += s;
    return r;
}

const std::string kTooDeep = "nesting deeper than 400 levels";

bool too_deep(const std::string& text) {
    return error_of(text).rfind(kTooDeep, 0) == 0;
}

TEST(Nesting, DeepParenthesesAreAnErrorNotACrash) {
    EXPECT_TRUE(too_deep("#declare A = " + repeat("(", 5000) + "1" + repeat(")", 5000) + ";"));
    EXPECT_EQ(error_of("#declare A = " + repeat("(", 300) + "1" + repeat(")", 300) + ";"),
              "no error");
}

TEST(Nesting, HundredThousandUnaryMinusesAreAnError) {
    EXPECT_TRUE(too_deep("#declare A = " + repeat("- ", 100000) + "1;"));
}

TEST(Nesting, HundredThousandTermSumIsOneFlatNode) {
    SourceFile f{"sum", "x" + repeat("+x", 100000)};
    ast::NodePtr n = parse_expression(f);
    ASSERT_EQ(n->kind, ast::Kind::Binary);
    EXPECT_EQ(n->children.size(), 100001u);
    EXPECT_EQ(n->more().ops.size(), 100000u);
    // Literals fold as they are read: the head and the last operand are left.
    SourceFile g{"sum", "1" + repeat("+1", 100000)};
    ast::NodePtr folded = parse_expression(g);
    ASSERT_EQ(folded->kind, ast::Kind::Binary);
    ASSERT_EQ(folded->children.size(), 2u);
    EXPECT_EQ(folded->children[0]->number, 100000);
}

TEST(Nesting, OtherDeepConstructs) {
    EXPECT_TRUE(too_deep(repeat("union {", 5000) + repeat("}", 5000)));
    EXPECT_TRUE(too_deep("#declare V = " + repeat("<", 5000) + "1" + repeat(">", 5000) + ";"));
    EXPECT_TRUE(too_deep(repeat("#if (1) ", 5000) + repeat("#end ", 5000)));
    EXPECT_TRUE(too_deep("color_map { " + repeat("[", 5000) + repeat("]", 5000) + "}"));
    EXPECT_TRUE(too_deep("#declare A = array[1] " + repeat("{", 5000) + repeat("}", 5000)));
    EXPECT_TRUE(too_deep("#declare A = " + repeat("f(", 5000) + "1" + repeat(")", 5000) + ";"));
    EXPECT_TRUE(too_deep("#declare A = " + repeat("rgb ", 5000) + "1;"));
    EXPECT_TRUE(too_deep("#declare A = a" + repeat(".x", 5000) + ";"));
    EXPECT_TRUE(too_deep("#declare A = " + repeat("1 ? 2 : ", 5000) + "3;"));
    // Nested comments are scanned by a loop: any depth is fine.
    EXPECT_EQ(expr(repeat("/*", 100000) + repeat("*/", 100000) + " 1"), "(Number 1)");
}

}  // namespace
}  // namespace lumen::parser

namespace lumen::parser {
namespace {

// Random token soup: every input either parses or gives a LumenError; nothing else escapes.
TEST(Robustness, RandomTokenSoupNeverCrashes) {
    const char* tokens[] = {"{", "}", "(", ")", "<", ">", "[", "]", ",", ";", "#if", "#else",
                            "#end", "#declare", "#macro", "#while", "#switch", "#case", "=",
                            "sphere", "x", "1", ".5", "\"s\"", "/*", "*/", "//", "\n", "-",
                            "+", "*", "?", ":", "rgb", "color", "array", "function", "#", "."};
    const std::size_t n = sizeof(tokens) / sizeof(tokens[0]);
    unsigned seed = 12345;
    auto next = [&] { return (seed = seed * 1103515245u + 12345u) >> 16; };
    int parsed = 0, rejected = 0;
    for (int round = 0; round < 3000; ++round) {
        std::string text;
        int len = int(next() % 40);
        for (int i = 0; i < len; ++i) {
            text += tokens[next() % n];
            text += ' ';
        }
        SourceFile f{"soup.pov", text};
        try {
            parse_file(f);
            ++parsed;
        } catch (const LumenError& e) {
            ++rejected;
            EXPECT_GE(e.diag.loc.line, 1u) << text;
            EXPECT_LE(e.diag.loc.byte, text.size()) << text;
        }
    }
    EXPECT_GT(parsed, 0);
    EXPECT_GT(rejected, 0);
}

}  // namespace
}  // namespace lumen::parser
