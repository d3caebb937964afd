// text { ttf "font.ttf" "string" thickness, offset modifiers }: the font is found on the
// scene's search path and read now; the string's characters become glyphs laid out as
// POV-Ray lays them out (see layout below).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "interp/build_common.hpp"
#include "interp/ttf_font.hpp"

namespace lumen::interp {

namespace {

// The UTF-8 sequence at s[i]: its code point and length, or length 0 when it is malformed.
uint32_t utf8_code(const std::string& s, size_t i, int& length) {
    const unsigned char b = static_cast<unsigned char>(s[i]);
    length = (b >> 5) == 6 ? 2 : (b >> 4) == 14 ? 3 : (b >> 3) == 30 ? 4 : 0;
    uint32_t code = b & (0x7f >> length);
    for (int k = 1; k < length; ++k) {
        const unsigned char c = i + k < s.size() ? static_cast<unsigned char>(s[i + k]) : 0;
        if ((c >> 6) != 2) {
            length = 0;
            return 0;
        }
        code = code << 6 | (c & 0x3f);
    }
    return code;
}

// The character codes of a string: its bytes under charset ascii, where POV-Ray replaces each
// byte outside ASCII by a space (and says so), or its UTF-8 code points.
std::vector<uint32_t> character_codes(ItemCursor& cur, const std::string& s, SourceLoc loc) {
    std::vector<uint32_t> codes;
    bool replaced = false;
    const bool utf8 = cur.ctx().utf8_strings;
    for (size_t i = 0; i < s.size();) {
        const unsigned char b = static_cast<unsigned char>(s[i]);
        int length = 0;
        const uint32_t code = b < 0x80 ? b : utf8 ? utf8_code(s, i, length) : 0;
        if (b < 0x80 || length > 0) {
            codes.push_back(code);
            i += std::max(length, 1);
        } else {
            codes.push_back(' ');
            replaced = true;
            ++i;
        }
    }
    if (replaced)
        cur.warn(loc, utf8 ? "invalid UTF-8 in the text string: replaced by spaces"
                           : "non-ASCII characters in the text string replaced by spaces "
                             "(global_settings { charset utf8 } reads them as UTF-8)");
    return codes;
}

// POV-Ray's layout, in em units: the first glyph is moved left by its xMin so that its ink
// starts at x = 0, and the pen starts at its advance less its left bearing. Each later glyph
// is placed at the pen plus its left bearing less its xMin plus the pair's kerning, and the pen
// moves on by the advance plus the kerning. After every glyph the pen moves by the offset's x
// and y too (its z is read but not used: POV-Ray keeps every glyph at z = 0).
std::vector<scene::Text::Glyph> layout(const TtfFont& font, const std::vector<uint32_t>& codes,
                                       bool unicode, const glm::dvec3& offset) {
    std::vector<scene::Text::Glyph> glyphs;
    glm::dvec3 pen(0);
    unsigned previous = 0;
    for (size_t i = 0; i < codes.size(); ++i) {
        const unsigned index = font.glyph_index(codes[i], unicode);
        FontGlyph g = font.glyph(index);
        scene::Text::Glyph placed;
        if (i == 0) {
            placed.position = {-g.x_min, 0, 0};
            pen.x = g.advance - g.left_bearing;
        } else {
            const double kern = font.kerning(previous, index);
            placed.position = pen + glm::dvec3(g.left_bearing - g.x_min + kern, 0, 0);
            pen.x += g.advance + kern;
        }
        pen += glm::dvec3(offset.x, offset.y, 0);
        placed.points = std::move(g.points);
        placed.contour_ends = std::move(g.contour_ends);
        glyphs.push_back(std::move(placed));
        previous = index;
    }
    return glyphs;
}

// `internal N`: POV-Ray 3.7's built-in fonts have the glyphs of the TrueType files that
// povray-includes ships (measured: identical renders): 0 povlogo, 1 timrom, 2 cyrvetic,
// 3 crystal; N is truncated and any other number is font 0.
std::string internal_font(double n) {
    static const char* const kFonts[] = {"povlogo.ttf", "timrom.ttf", "cyrvetic.ttf",
                                         "crystal.ttf"};
    const double k = std::trunc(n);
    return kFonts[k >= 0 && k < 4 ? static_cast<int>(k) : 0];
}

}  // namespace

scene::ObjectPtr build_text(ItemCursor& cur) {
    scene::Object obj;
    obj.loc = cur.block_loc();
    std::string name;
    if (cur.accept_keyword("internal")) {
        name = internal_font(cur.expect_float("internal"));
    } else {
        if (!cur.accept_keyword("ttf"))
            cur.fail_expected("'ttf' and a font file name, or 'internal' and a font number",
                              "text");
        name = cur.expect_string("ttf");
    }
    const SourceLoc font_loc = cur.here();
    scene::Text text;
    text.string = cur.expect_string("the font file name");
    const SourceLoc string_loc = cur.here();
    text.thickness = cur.expect_float("the text string");
    text.offset = cur.expect_vector("the text thickness");
    text.font = FileResolver(cur.ctx().search_path).find(name, FileResolver::Kind::Font);
    if (text.font.empty()) cur.fail(font_loc, "cannot find font file '" + name + "'");
    try {
        const TtfFont font(text.font);
        text.glyphs = layout(font, character_codes(cur, text.string, string_loc),
                             cur.ctx().utf8_strings, text.offset);
    } catch (const std::runtime_error& e) {
        cur.fail(font_loc, "cannot read font file '" + text.font + "': " + e.what());
    }
    obj.shape = std::move(text);
    // POV-Ray turns every text by 0.001 degrees about x, y and z before the modifiers (against
    // cracks where glyph walls line up with the view); textures given later do not turn.
    obj.transform = rotation(glm::dvec3(0.001));
    read_object_modifiers(cur, obj, [](const Item&) { return false; }, {});
    return std::make_shared<scene::Object>(std::move(obj));
}

}  // namespace lumen::interp
