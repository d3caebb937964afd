// Smoke tests for the SDL parser: the tree shapes the interpreter relies on.
#include <gtest/gtest.h>

#include "parser/dump.hpp"
#include "parser/parser.hpp"

namespace lumen::parser {
namespace {

std::string parse_dump(const std::string& text) {
    SourceFile f{"test.pov", text};
    return dump(*parse_file(f));
}

std::string expr_dump(const std::string& text) {
    SourceFile f{"expr", text};
    return dump(*parse_expression(f));
}

TEST(ParserSmoke, SphereBlock) {
    EXPECT_EQ(parse_dump("sphere { <0,0,0>, 1 }"),
              "(Body (Block sphere (Vector (Number 0) (Number 0) (Number 0)) (Comma) (Number 1)))");
}

TEST(ParserSmoke, Precedence) {
    EXPECT_EQ(expr_dump("1+2*3"), "(Binary (Number 1) + (Binary (Number 2) * (Number 3)))");
}

}  // namespace
}  // namespace lumen::parser
