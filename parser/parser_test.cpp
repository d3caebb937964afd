// Grammar-wide checks: PEGTL's static analysis and a smoke parse.
#include <gtest/gtest.h>

#include <tao/pegtl/contrib/analyze.hpp>

#include "parser/grammar.hpp"
#include "parser/test_util.hpp"

// The custom rules tell analyze() what they consume: words and delimited tokens always
// consume input; a raw macro body and white space may be empty.
namespace tao::pegtl {
template <typename Name, bool (*P)(std::string_view)>
struct analyze_traits<Name, lumen::parser::rules::word_if<P>> : analyze_any_traits<> {};
template <typename Name, char C0, char C1, const char* (*S)(const char*, const char*), typename E>
struct analyze_traits<Name, lumen::parser::rules::delimited<C0, C1, S, E>> : analyze_any_traits<> {};
template <typename Name>
struct analyze_traits<Name, lumen::parser::rules::macro_raw_body> : analyze_opt_traits<> {};
template <typename Name>
struct analyze_traits<Name, lumen::parser::rules::sep> : analyze_opt_traits<> {};
}  // namespace tao::pegtl

namespace lumen::parser {
namespace {

TEST(Grammar, HasNoInfiniteLoopsOrLeftRecursion) {
    EXPECT_EQ(tao::pegtl::analyze<rules::file>(-1), 0u);
    EXPECT_EQ(tao::pegtl::analyze<rules::single_expression>(-1), 0u);
}

TEST(Grammar, SmokeParse) {
    EXPECT_EQ(testing::items("sphere { <0,0,0>, 1 }"),
              "(Block sphere (Vector (Number 0) (Number 0) (Number 0)) (Comma) (Number 1))");
    EXPECT_EQ(testing::expr("1+2*3"), "(Binary (Number 1) + (Binary (Number 2) * (Number 3)))");
}

}  // namespace
}  // namespace lumen::parser
