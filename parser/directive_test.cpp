// Directives and block items: the node shapes the interpreter walks.
#include <gtest/gtest.h>

#include "parser/test_util.hpp"

namespace lumen::parser {
namespace {

using testing::items;
using testing::parse_text;

TEST(Items, BlocksKeywordsCommasAndMaps) {
    EXPECT_EQ(items("sphere { <0,0,0>, 1 translate x*2 hollow }"),
              "(Block sphere (Vector (Number 0) (Number 0) (Number 0)) (Comma) (Number 1)"
              " (Keyword translate) (Binary (Ident x) * (Number 2)) (Keyword hollow))");
    EXPECT_EQ(items("color_map { [0 color Red] [1 rgb 1] }"),
              "(Block color_map (MapEntry (Number 0) (Colour (ColourPart (Ident Red))))"
              " (MapEntry (Number 1) (Colour (ColourPart rgb (Number 1)))))");
    EXPECT_EQ(items("a; b"), "(Ident a) (Semicolon) (Ident b)");
}

// A vector item is read by itself only where no operator, member or index follows it.
TEST(Items, VectorItemsAndTheExpressionsThatContinueThem) {
    EXPECT_EQ(items("m { <1,2,3>, <4,5,6> }"),
              "(Block m (Vector (Number 1) (Number 2) (Number 3)) (Comma)"
              " (Vector (Number 4) (Number 5) (Number 6)))");
    EXPECT_EQ(items("m { <1,2,3> + <1,1,1> }"),
              "(Block m (Binary (Vector (Number 1) (Number 2) (Number 3)) +"
              " (Vector (Number 1) (Number 1) (Number 1))))");
    EXPECT_EQ(items("m { <1,2,3> -<1,1,1> <1,2>.x <1,2>[0] }"),
              "(Block m (Binary (Vector (Number 1) (Number 2) (Number 3)) -"
              " (Vector (Number 1) (Number 1) (Number 1)))"
              " (Member x (Vector (Number 1) (Number 2)))"
              " (Index (Vector (Number 1) (Number 2)) (Number 0)))");
    EXPECT_EQ(items("m { <1,2> <3,4> translate <5,6> }"),
              "(Block m (Vector (Number 1) (Number 2)) (Vector (Number 3) (Number 4))"
              " (Keyword translate) (Vector (Number 5) (Number 6)))");
}

TEST(Items, UnknownWordsStillFormBlocks) {
    EXPECT_EQ(items("spere { 1 }"), "(Block spere (Number 1))");
}

TEST(Items, KeywordFollowedByParenthesesIsNotACall) {
    EXPECT_EQ(items("rotate (x*90)"), "(Keyword rotate) (Binary (Ident x) * (Number 90))");
}

TEST(Items, FunctionBlocks) {
    EXPECT_EQ(items("function(x, y, z) { x*y }"),
              "(Block function [x y z] (Binary (Ident x) * (Ident y)))");
    EXPECT_EQ(items("function { pattern { checker } }"),
              "(Block function (Block pattern (Keyword checker)))");
    auto p = parse_text("height_field { function 300, 200 { x } }");
    const ast::Node& fn = *p.root->children[0]->children[0];
    EXPECT_EQ(fn.text, "function");
    EXPECT_TRUE(fn.flag);
    EXPECT_EQ(dump(fn), "(Block function (Number 300) (Number 200) (Ident x))");
}

TEST(Declare, SimpleAndLocal) {
    EXPECT_EQ(items("#declare A = 1; #local B = <1,2>"),
              "(Declare declare (Ident A) (Number 1)) "
              "(Declare local (Ident B) (Vector (Number 1) (Number 2)))");
    EXPECT_EQ(items("# declare S = sphere { 0, 1 }"),
              "(Declare declare (Ident S) (Block sphere (Number 0) (Comma) (Number 1)))");
}

TEST(Declare, IndexedTarget) {
    EXPECT_EQ(items("#declare A[i][j] = 2;"),
              "(Declare declare (Index (Ident A) (Ident i) (Ident j)) (Number 2))");
}

TEST(Declare, LayeredTextureAbsorbsFollowingTextures) {
    EXPECT_EQ(items("#declare T = texture { A } texture { B } sphere { 0, 1 }"),
              "(Declare declare (Ident T) (Block texture (Ident A)) (Block texture (Ident B)))"
              " (Block sphere (Number 0) (Comma) (Number 1))");
}

TEST(Declare, ArrayFunctionAndDeprecated) {
    EXPECT_EQ(items("#declare A = array[2] {1, 2};"),
              "(Declare declare (Ident A) (ArrayDecl init (Number 2) (ArrayInit (Number 1) (Number 2))))");
    EXPECT_EQ(items("#declare F = function(x) { x }"),
              "(Declare declare (Ident F) (Block function [x] (Ident x)))");
    EXPECT_EQ(items("#declare deprecated once \"old\" T = 1;"),
              "(Declare declare (Ident T) (Number 1))");
}

TEST(Conditionals, IfElseifElse) {
    EXPECT_EQ(items("#if (a) 1 #elseif (b) 2 #else 3 #end"),
              "(If (Branch (Ident a) (Body (Number 1))) (Branch (Ident b) (Body (Number 2)))"
              " (Branch (Null) (Body (Number 3))))");
}

TEST(Conditionals, IfInsideBlock) {
    EXPECT_EQ(items("sphere { 0, 1 #if (a) hollow #end }"),
              "(Block sphere (Number 0) (Comma) (Number 1)"
              " (If (Branch (Ident a) (Body (Keyword hollow)))))");
}

TEST(Conditionals, IfdefAndIfndef) {
    EXPECT_EQ(items("#ifdef (A) 1 #else 2 #end"),
              "(Ifdef ifdef (Ident A) (Branch (Null) (Body (Number 1))) (Branch (Null) (Body (Number 2))))");
    EXPECT_EQ(items("#ifndef (A[1]) 1 #end"),
              "(Ifdef ifndef (Index (Ident A) (Number 1)) (Branch (Null) (Body (Number 1))))");
}

TEST(Conditionals, Switch) {
    EXPECT_EQ(items("#switch (n) #case (1) a #break #range (2, 3) b #else c #end"),
              "(Switch (Ident n) (Case (Number 1) (Body (Ident a) (Break)))"
              " (Range (Number 2) (Number 3) (Body (Ident b))) (Branch (Null) (Body (Ident c))))");
}

TEST(Loops, WhileAndFor) {
    EXPECT_EQ(items("#while (i < 3) #declare i = i + 1; #end"),
              "(While (Binary (Ident i) < (Number 3)) (Body (Declare declare (Ident i)"
              " (Binary (Ident i) + (Number 1)))))");
    EXPECT_EQ(items("#for (I, 1, 10) I #end"),
              "(For I (Number 1) (Number 10) (Null) (Body (Ident I)))");
    EXPECT_EQ(items("#for (I, 10, 1, -1) #end"),
              "(For I (Number 10) (Number 1) (Unary - (Number 1)) (Body))");
}

TEST(Macros, RawBodyIsRecordedNotParsed) {
    const std::string text =
        "#macro M(A, optional B)\n"
        "  #if (A) sphere { 0, B } #end // #end in a comment\n"
        "  \"#end in a string\" /* #end /* nested */ */\n"
        "#end\n"
        "M(1, 2)";
    auto p = parse_text(text);
    const ast::Node& m = *p.root->children[0];
    ASSERT_EQ(m.kind, ast::Kind::Macro);
    EXPECT_EQ(m.text, "M");
    EXPECT_EQ(m.more().params, (std::vector<std::string>{"A", "B"}));
    EXPECT_EQ(m.more().optional_params, (std::vector<bool>{false, true}));
    EXPECT_EQ(m.more().raw_loc.line, 1u);
    EXPECT_EQ(m.more().raw_loc.column, 24u);
    std::string raw = text.substr(m.more().raw_begin, m.more().raw_end - m.more().raw_begin);
    EXPECT_EQ(raw.substr(raw.size() - 1), "\n");
    EXPECT_NE(raw.find("nested */ */"), std::string::npos);
    EXPECT_EQ(dump(*p.root->children[1]), "(Call M (Number 1) (Number 2))");

    // The body parses on demand, with locations in the original file.
    ast::NodePtr body = parse_fragment(*p.file, m.more().raw_begin, m.more().raw_end, m.more().raw_loc);
    ASSERT_EQ(body->children.size(), 2u);
    const ast::Node& if_node = *body->children[0];
    EXPECT_EQ(if_node.kind, ast::Kind::If);
    EXPECT_EQ(if_node.loc.line, 2u);
    EXPECT_EQ(if_node.loc.column, 3u);
    EXPECT_EQ(body->children[1]->kind, ast::Kind::String);
    EXPECT_EQ(body->children[1]->loc.line, 3u);
}

TEST(Macros, NestedDirectivesFindTheMatchingEnd) {
    auto p = parse_text("#macro M() #while (1) #for (i,0,1) #end #end #macro N() #end #end 5");
    ASSERT_EQ(p.root->children.size(), 2u);
    EXPECT_EQ(p.root->children[0]->kind, ast::Kind::Macro);
    EXPECT_EQ(dump(*p.root->children[1]), "(Number 5)");
}

TEST(Macros, ParametersWithoutCommasAndTrailingComma) {
    auto p = parse_text("#macro M(A B, C,) #end");
    EXPECT_EQ(p.root->children[0]->more().params, (std::vector<std::string>{"A", "B", "C"}));
}

TEST(OtherDirectives, VersionIncludeUndefDefaultMessages) {
    EXPECT_EQ(items("#version 3.7; #include \"colors.inc\" #undef A"),
              "(Version (Number 3.7)) (Include (String \"colors.inc\")) (Undef A)");
    EXPECT_EQ(items("#default { finish { ambient 0 } }"),
              "(Default (Block finish (Keyword ambient) (Number 0)))");
    EXPECT_EQ(items("#debug \"x\" #warning \"y\" #error \"z\""),
              "(Message debug (String \"x\")) (Message warning (String \"y\")) (Message error (String \"z\"))");
    auto p = parse_text("#version unofficial megapov 1.0;");
    EXPECT_EQ(p.root->children[0]->text.substr(0, 10), "unofficial");
}

TEST(OtherDirectives, FileIoIsParsedLoosely) {
    EXPECT_EQ(items("#fopen F \"out.txt\" write #write (F, \"a\", uint16be <1,2>,) #fclose F"),
              "(FileIO fopen (Ident F) (String \"out.txt\") (Ident write))"
              " (FileIO write (Ident F) (String \"a\") (Keyword uint16be) (Vector (Number 1) (Number 2)))"
              " (FileIO fclose (Ident F))");
}

TEST(Locations, NodesCarryLineColumnAndByte) {
    auto p = parse_text("// comment\n  sphere {\n\t<1,2,3> }");
    const ast::Node& s = *p.root->children[0];
    EXPECT_EQ(s.loc.line, 2u);
    EXPECT_EQ(s.loc.column, 3u);
    EXPECT_EQ(s.loc.byte, 13u);
    EXPECT_EQ(s.loc.file, p.file.get());
    const ast::Node& v = *s.children[0];
    EXPECT_EQ(v.loc.line, 3u);
    EXPECT_EQ(v.loc.column, 2u);
    const ast::Node& two = *v.children[1];
    EXPECT_EQ(two.loc.column, 5u);
}

TEST(Comments, BlockCommentsNest) {
    EXPECT_EQ(items("/* a /* b */ c */ 1 // x\n2"), "(Number 1) (Number 2)");
}

}  // namespace
}  // namespace lumen::parser

namespace lumen::parser {
namespace {

using testing::items;

TEST(ConditionalBlocks, KeywordChosenByIf) {
    // shapes.inc: #if (UseMerge) merge { #else union { #end ... }
    EXPECT_EQ(items("#if (M) merge { #else union { #end sphere { 0, 1 } }"),
              "(If (Branch (Ident M) (Body (Block merge (Block sphere (Number 0) (Comma) (Number 1)))))"
              " (Branch (Null) (Body (Block union (Block sphere (Number 0) (Comma) (Number 1))))))");
}

TEST(ConditionalBlocks, OpenedAndClosedUnderTheSameCondition) {
    // shapes3.inc: #if (A > 180) merge { #end ... #if (A > 180) } #end
    EXPECT_EQ(items("#if (A) merge { #end box { 0, 1 } #if (A) } #end"),
              "(If (Branch (Ident A) (Body (Block merge (Block box (Number 0) (Comma) (Number 1)))))"
              " (Branch (Null) (Body (Block box (Number 0) (Comma) (Number 1)))))");
}

TEST(ConditionalBlocks, OrdinaryIfIsUnaffected) {
    EXPECT_EQ(items("#if (M) merge { } #else union { } #end"),
              "(If (Branch (Ident M) (Body (Block merge))) (Branch (Null) (Body (Block union))))");
}

}  // namespace
}  // namespace lumen::parser
