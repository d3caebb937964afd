// Scanning and blanking a macro body's decided conditionals (conditional_text.hpp).
#include "interp/conditional_text.hpp"

#include <gtest/gtest.h>

#include <map>

namespace lumen::interp {
namespace {

std::string_view range(std::string_view text, uint32_t begin, uint32_t end) {
    return text.substr(begin, end - begin);
}

TEST(ConditionalText, ScansGroupsAtEveryDepthSkippingStringsAndComments) {
    const std::string text =
        "#if (A) x #elseif (B) y #else z #end\n"
        "\"#if (S)\" // #if (C)\n"
        "/* #if (D) /* nested */ #end */\n"
        "#while (I < 3) #if (E) #ifdef (F) #else #end #end #local I = I + 1; #end\n"
        "#declare Out = 1;";
    const ConditionalScan scan = scan_conditionals(text, 0, uint32_t(text.size()));
    ASSERT_EQ(scan.groups.size(), 2u);
    const ConditionalGroup& g = scan.groups[0];
    ASSERT_EQ(g.branches.size(), 3u);
    EXPECT_EQ(range(text, g.branches[0].cond_begin, g.branches[0].head_end), "(A)");
    EXPECT_EQ(range(text, g.branches[0].head_end, g.branches[0].body_end), " x ");
    EXPECT_EQ(range(text, g.branches[1].cond_begin, g.branches[1].head_end), "(B)");
    EXPECT_FALSE(g.branches[2].has_condition());
    EXPECT_EQ(range(text, g.branches[2].head_end, g.branches[2].body_end), " z ");
    EXPECT_EQ(range(text, g.end_begin, g.end_end), "#end");
    // The #else of the #ifdef inside the second group is not the group's.
    ASSERT_EQ(scan.groups[1].branches.size(), 1u);
    EXPECT_EQ(range(text, scan.groups[1].branches[0].cond_begin, scan.groups[1].branches[0].head_end),
              "(E)");
    EXPECT_EQ(scan.assigned, (std::set<std::string>{"I", "Out"}));
}

TEST(ConditionalText, BlanksUntakenBranchesAndDirectivesKeepingOffsets) {
    const std::string text = "#if (W) open( #else [\n#end 1, 2\n#if (W) ) #else ] #end";
    const ConditionalScan scan = scan_conditionals(text, 0, uint32_t(text.size()));
    const auto no = [](uint32_t, uint32_t) -> std::optional<bool> { return false; };
    const auto out = blank_decided_conditionals(text, scan, no);
    ASSERT_TRUE(out);
    EXPECT_EQ(out->size(), text.size());
    EXPECT_EQ(*out, "                    [\n     1, 2\n                ]     ");
    const auto yes = [](uint32_t, uint32_t) -> std::optional<bool> { return true; };
    EXPECT_EQ(*blank_decided_conditionals(text, scan, yes),
              "        open(        \n     1, 2\n        )             ");
}

TEST(ConditionalText, UndecidedAndDroppedGroupsAreLeftOrSkipped) {
    const std::string text = "#if (A) #if (B) b #end #end #if (C) c #end #if D d #end";
    const ConditionalScan scan = scan_conditionals(text, 0, uint32_t(text.size()));
    ASSERT_EQ(scan.groups.size(), 4u);
    EXPECT_FALSE(scan.groups[3].decidable);  // a condition without parentheses
    std::map<std::string, int> asked;
    const auto decide = [&](uint32_t b, uint32_t e) -> std::optional<bool> {
        const std::string cond(range(text, b, e));
        ++asked[cond];
        if (cond == "(C)") return std::nullopt;
        return false;
    };
    const auto out = blank_decided_conditionals(text, scan, decide);
    ASSERT_TRUE(out);
    // (B) lies in A's dropped branch: never evaluated. C undecided: left as written.
    EXPECT_EQ(asked, (std::map<std::string, int>{{"(A)", 1}, {"(C)", 1}}));
    EXPECT_EQ(out->substr(28), "#if (C) c #end #if D d #end");
    EXPECT_EQ(out->substr(0, 28), std::string(28, ' '));
    const auto never = [](uint32_t, uint32_t) -> std::optional<bool> { return std::nullopt; };
    EXPECT_FALSE(blank_decided_conditionals(text, scan, never));
}

TEST(ConditionalText, ConditionIdentifiers) {
    EXPECT_EQ(condition_identifiers("(strlen(Name) > 0 & V.x < 1e3 & \"Q\" = S)"),
              (std::vector<std::string>{"strlen", "Name", "V", "S"}));
}

}  // namespace
}  // namespace lumen::interp
