// A TrueType font read through FreeType into what `text` needs, in em units (font units
// divided by the font's unitsPerEm): glyph outlines as stored (no hinting), horizontal metrics,
// glyph boxes and kerning pairs, and the character map POV-Ray chooses.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "scene/shapes.hpp"

namespace lumen::interp {

struct FontGlyph {
    std::vector<scene::Text::Point> points;  // every contour, in the font's order
    std::vector<int> contour_ends;           // one past each contour's last point
    double advance = 0;                      // hmtx advance width
    double left_bearing = 0;                 // hmtx left side bearing
    double x_min = 0;  // the header's xMin or the least x of the points if less (0: blank)
};

class TtfFont {
public:
    // The font at `path`; throws std::runtime_error saying why it cannot be read.
    explicit TtfFont(const std::string& path);
    ~TtfFont();
    TtfFont(const TtfFont&) = delete;
    TtfFont& operator=(const TtfFont&) = delete;

    // The glyph of a character code (0, the missing-glyph box, when the font has none). POV-Ray
    // looks the code up in the first character map of platform 1 (Macintosh), 3 (Windows) or
    // 0 (Unicode), in that order for ASCII strings and in the order 0, 3, 1 for UTF-8 ones.
    unsigned glyph_index(uint32_t code, bool unicode_strings) const;
    FontGlyph glyph(unsigned index) const;
    // The kern table's horizontal adjustment between two glyphs, never below -1 em.
    double kerning(unsigned left, unsigned right) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace lumen::interp
