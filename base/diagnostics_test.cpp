// Diagnostics: message layout and "did you mean" suggestions.
#include "base/diagnostics.hpp"

#include <gtest/gtest.h>

namespace lumen {
namespace {

TEST(DidYouMean, SuggestsCloseWordsOnly) {
    const std::vector<std::string> words{"sphere", "plane", "Red", "Width", "Height"};
    EXPECT_EQ(closest_match("spere", words), "sphere");
    EXPECT_EQ(closest_match("Rde", words), "Red");      // adjacent letters swapped
    EXPECT_EQ(closest_match("Widht", words), "Width");  // adjacent letters swapped
    EXPECT_EQ(closest_match("torus", words), "");       // nothing close
    EXPECT_EQ(closest_match("plane", words), "");       // exact: no suggestion
    EXPECT_EQ(did_you_mean("spere", words), "did you mean 'sphere'?");
}

TEST(FormatDiagnostic, LineCaretAndHint) {
    SourceFile f{"scene.pov", "camera {}\n  spere { 0, 1 }\n"};
    Diagnostic d{Severity::Error, SourceLoc{&f, 2, 3, 12}, "unknown keyword 'spere'",
                 "did you mean 'sphere'?", {}};
    EXPECT_EQ(format_diagnostic(d),
              "scene.pov:2:3: error: unknown keyword 'spere'\n"
              "      spere { 0, 1 }\n"
              "      ^\n"
              "scene.pov:2:3: note: did you mean 'sphere'?\n");
}

}  // namespace
}  // namespace lumen
