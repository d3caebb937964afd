#include "base/warning_log.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace lumen {
namespace {

TEST(WarningLog, PrintsAWarningOncePerLocationAndCountsTheRest) {
    SourceManager sources;
    const SourceFile* f = sources.add("s.pov", "line\nline\n");
    const SourceLoc a{f, 1, 1, 0}, b{f, 2, 1, 5};
    std::vector<Diagnostic> printed;
    WarningLog log([&](const Diagnostic& d) { printed.push_back(d); });
    for (int i = 0; i < 1000; ++i) log.report({Severity::Warning, b, "degenerate triangle", {}, {}});
    log.report({Severity::Warning, a, "twice", {}, {}});
    log.report({Severity::Warning, a, "twice", {}, {}});
    log.report({Severity::Warning, a, "other text", {}, {}});
    log.report({Severity::Note, a, "#debug", {}, {}});
    log.report({Severity::Note, a, "#debug", {}, {}});
    ASSERT_EQ(printed.size(), 5u);  // b once, a once per text, both notes
    EXPECT_EQ(log.count(b, "degenerate triangle"), 1000u);
    EXPECT_EQ(log.count(a, "twice"), 2u);
    printed.clear();
    log.flush();
    ASSERT_EQ(printed.size(), 2u);  // in source order: a, then b
    EXPECT_EQ(printed[0].severity, Severity::Note);
    EXPECT_EQ(printed[0].loc.line, 1u);
    EXPECT_NE(printed[0].message.find("2 times"), std::string::npos);
    EXPECT_NE(printed[1].message.find("1000 times"), std::string::npos);
    EXPECT_EQ(log.count(b, "degenerate triangle"), 0u);  // flushed
}

}  // namespace
}  // namespace lumen
