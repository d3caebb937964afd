// text through the whole interpreter: the font found on the include path, POV-Ray's layout
// (first-glyph shift, kerning, offset), the string's charset, and located errors.
#include <algorithm>

#include "interp/build_test_support.hpp"
#include "interp/ttf_font.hpp"

namespace lumen::interp::testing {
namespace {

using BuildText = BuildTest;

const char* const kTimrom = "/usr/share/povray-3.7/include/timrom.ttf";

double ink_left(const scene::Text::Glyph& g) {
    double x = 1e30;
    for (const auto& p : g.points) x = std::min(x, p.p.x);
    return x + g.position.x;
}

TEST_F(BuildText, FontFoundOnTheIncludePathAndStringKept) {
    auto t = shape_of<scene::Text>("text { ttf \"timrom\" \"Hi\" 0.25, 0 }");
    EXPECT_EQ(t.font, kTimrom);  // ".ttf" added, as POV-Ray does
    EXPECT_EQ(t.string, "Hi");
    EXPECT_DOUBLE_EQ(t.thickness, 0.25);
    ASSERT_EQ(t.glyphs.size(), 2u);
    EXPECT_FALSE(t.glyphs[0].points.empty());
    EXPECT_EQ(t.glyphs[0].contour_ends.back(), int(t.glyphs[0].points.size()));
}

TEST_F(BuildText, InternalFontsAreTheIncludedTrueTypeFonts) {
    // Measured: POV-Ray 3.7's internal fonts render as these files; other numbers are font 0.
    const std::pair<const char*, const char*> cases[] = {
        {"0", "povlogo.ttf"}, {"1", "timrom.ttf"},  {"2.9", "cyrvetic.ttf"},
        {"3", "crystal.ttf"}, {"4", "povlogo.ttf"}, {"7", "povlogo.ttf"}};
    for (const auto& [n, file] : cases) {
        auto t = shape_of<scene::Text>(std::string("text { internal ") + n + " \"Ab\" 1, 0 }");
        EXPECT_EQ(t.font, std::string("/usr/share/povray-3.7/include/") + file) << n;
        EXPECT_EQ(t.glyphs.size(), 2u);
    }
}

TEST_F(BuildText, FirstGlyphInkStartsAtZeroAndKerningApplies) {
    const TtfFont font(kTimrom);
    const unsigned a = font.glyph_index('A', false), v = font.glyph_index('V', false);
    const FontGlyph ga = font.glyph(a), gv = font.glyph(v);
    EXPECT_NEAR(font.kerning(a, v), -0.187, 1e-12);  // timrom's kern pair A-V: -187/1000 em
    auto t = shape_of<scene::Text>("text { ttf \"timrom.ttf\" \"AV\" 1, 0 }");
    ASSERT_EQ(t.glyphs.size(), 2u);
    EXPECT_NEAR(ink_left(t.glyphs[0]), 0, 1e-12);
    EXPECT_DOUBLE_EQ(t.glyphs[0].position.x, -ga.x_min);
    const double pen = ga.advance - ga.left_bearing;
    EXPECT_NEAR(t.glyphs[1].position.x, pen + gv.left_bearing - gv.x_min - 0.187, 1e-12);
}

TEST_F(BuildText, OffsetMovesEveryLaterGlyphInXAndYOnly) {
    auto plain = shape_of<scene::Text>("text { ttf \"timrom.ttf\" \"HHH\" 1, 0 }");
    auto spread = shape_of<scene::Text>("text { ttf \"timrom.ttf\" \"HHH\" 1, <0.1, 0.2, 0.3> }");
    for (int i = 0; i < 3; ++i) {
        const glm::dvec3 d = spread.glyphs[i].position - plain.glyphs[i].position;
        EXPECT_NEAR(d.x, 0.1 * i, 1e-12);
        EXPECT_NEAR(d.y, 0.2 * i, 1e-12);
        EXPECT_EQ(d.z, 0);  // POV-Ray reads the z but keeps the glyphs at z = 0
    }
    auto single = shape_of<scene::Text>("text { ttf \"timrom.ttf\" \"H\" 1, 0.5 }");
    EXPECT_DOUBLE_EQ(single.offset.y, 0.5);  // a float offset is <f, f, f>
}

TEST_F(BuildText, EmptyBlankAndMissingCharacters) {
    EXPECT_TRUE(shape_of<scene::Text>("text { ttf \"timrom.ttf\" \"\" 1, 0 }").glyphs.empty());
    auto blank = shape_of<scene::Text>("text { ttf \"timrom.ttf\" \" \" 1, 0 }");
    ASSERT_EQ(blank.glyphs.size(), 1u);
    EXPECT_TRUE(blank.glyphs[0].points.empty());
    // U+20AC is not in timrom.ttf: glyph 0, the missing-glyph box, stands for it.
    auto euro = shape_of<scene::Text>(
        "global_settings { charset utf8 } text { ttf \"timrom.ttf\" \"\xe2\x82\xac\" 1, 0 }");
    ASSERT_EQ(euro.glyphs.size(), 1u);
    EXPECT_EQ(euro.glyphs[0].points.size(), TtfFont(kTimrom).glyph(0).points.size());
    EXPECT_FALSE(euro.glyphs[0].points.empty());
}

TEST_F(BuildText, AsciiCharsetTurnsEachNonAsciiByteIntoASpace) {
    const std::string e_acute = "\xc3\xa9";
    auto ascii = shape_of<scene::Text>("text { ttf \"timrom.ttf\" \"a" + e_acute + "\" 1, 0 }");
    ASSERT_EQ(ascii.glyphs.size(), 3u);
    EXPECT_TRUE(ascii.glyphs[1].points.empty() && ascii.glyphs[2].points.empty());
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].message.find("replaced by spaces"), std::string::npos);
    auto utf8 = shape_of<scene::Text>("global_settings { charset utf8 } text { ttf "
                                      "\"timrom.ttf\" \"a" + e_acute + "\" 1, 0 }");
    EXPECT_EQ(utf8.glyphs.size(), 2u);
}

TEST_F(BuildText, TurnedByAThousandthOfADegreeBeforeItsModifiers) {
    scene::ObjectPtr o = first_object("text { ttf \"timrom.ttf\" \"A\" 1, 0 translate <5, 0, 0> }");
    const glm::dvec3 p = o->transform.point({1, 0, 0});
    EXPECT_NEAR(p.x, 6, 1e-9);
    EXPECT_NE(p.y, 0);  // the turn about z moves +x a hair up
    EXPECT_NEAR(std::abs(p.y), 1.745e-5, 1e-7);
}

TEST_F(BuildText, MissingOrUnreadableFontIsALocatedError) {
    EXPECT_EQ(error_of("\ntext { ttf \"nofont.ttf\" \"A\" 1, 0 }"),
              "t.pov:2:12: error: cannot find font file 'nofont.ttf'");
    const std::string bad = error_of("text { ttf \"colors.inc\" \"A\" 1, 0 }");
    EXPECT_NE(bad.find("t.pov:1:12: error: cannot read font file"), std::string::npos) << bad;
    EXPECT_NE(error_of("text { \"timrom.ttf\" \"A\" 1, 0 }").find("'ttf'"), std::string::npos);
    EXPECT_NE(error_of("text { ttf \"timrom.ttf\" \"A\" }").find("error"), std::string::npos);
}

}  // namespace
}  // namespace lumen::interp::testing
