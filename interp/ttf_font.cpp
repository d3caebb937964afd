// FreeType gives the outlines (FT_LOAD_NO_SCALE: the points in font units, exactly as the
// glyf table stores them) and the kerning; the horizontal metrics and the glyph header boxes,
// which POV-Ray reads from the tables directly, come from the raw hmtx, loca and glyf tables.
#include "interp/ttf_font.hpp"

#include <algorithm>
#include <stdexcept>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_TRUETYPE_TABLES_H
#include FT_TRUETYPE_TAGS_H

namespace lumen::interp {

namespace {

// A raw sfnt table (empty when the font has none).
std::vector<unsigned char> raw_table(FT_Face face, FT_ULong tag) {
    FT_ULong length = 0;
    if (FT_Load_Sfnt_Table(face, tag, 0, nullptr, &length) != 0) return {};
    std::vector<unsigned char> bytes(length);
    if (length && FT_Load_Sfnt_Table(face, tag, 0, bytes.data(), &length) != 0) return {};
    return bytes;
}

// Big-endian fields of a raw table; 0 past its end.
unsigned u16(const std::vector<unsigned char>& t, size_t at) {
    return at + 2 <= t.size() ? unsigned(t[at]) << 8 | t[at + 1] : 0;
}
int s16(const std::vector<unsigned char>& t, size_t at) { return int16_t(u16(t, at)); }
unsigned long u32(const std::vector<unsigned char>& t, size_t at) {
    return (unsigned long)u16(t, at) << 16 | u16(t, at + 2);
}

}  // namespace

struct TtfFont::Impl {
    FT_Library library = nullptr;
    FT_Face face = nullptr;
    double per_unit = 1;  // 1 / unitsPerEm
    bool long_loca = false;
    unsigned h_metrics = 0;  // hhea.numberOfHMetrics
    std::vector<unsigned char> hmtx, loca;
    FT_CharMap ascii_map = nullptr, unicode_map = nullptr;

    // The first character map of the first of `platforms` the font has, among the formats
    // POV-Ray reads (0, 4 and 6).
    FT_CharMap charmap_of(std::initializer_list<int> platforms) const {
        for (int platform : platforms) {
            for (int i = 0; i < face->num_charmaps; ++i) {
                FT_CharMap map = face->charmaps[i];
                const long format = FT_Get_CMap_Format(map);
                if (map->platform_id == platform && (format == 0 || format == 4 || format == 6))
                    return map;
            }
        }
        return nullptr;
    }

    // The glyph header's xMin, from loca and glyf; 0 for a glyph without data.
    double x_min(unsigned index) const {
        unsigned long from, to;
        if (long_loca) {
            from = u32(loca, 4 * size_t(index));
            to = u32(loca, 4 * size_t(index) + 4);
        } else {
            from = 2ul * u16(loca, 2 * size_t(index));
            to = 2ul * u16(loca, 2 * size_t(index) + 2);
        }
        if (to <= from) return 0;
        unsigned char header[4];
        FT_ULong length = sizeof header;
        if (FT_Load_Sfnt_Table(face, TTAG_glyf, from, header, &length) != 0) return 0;
        return int16_t(header[2] << 8 | header[3]) * per_unit;
    }
};

TtfFont::TtfFont(const std::string& path) : impl_(std::make_unique<Impl>()) {
    Impl& f = *impl_;
    if (FT_Init_FreeType(&f.library) != 0) throw std::runtime_error("FreeType cannot start");
    if (FT_New_Face(f.library, path.c_str(), 0, &f.face) != 0)
        throw std::runtime_error("not a font file FreeType can read");
    const auto* head = static_cast<const TT_Header*>(FT_Get_Sfnt_Table(f.face, FT_SFNT_HEAD));
    const auto* hhea = static_cast<const TT_HoriHeader*>(FT_Get_Sfnt_Table(f.face, FT_SFNT_HHEA));
    if (!head || !hhea || head->Units_Per_EM == 0 || !FT_IS_SFNT(f.face))
        throw std::runtime_error("not a TrueType font");
    f.per_unit = 1.0 / head->Units_Per_EM;
    f.long_loca = head->Index_To_Loc_Format != 0;
    f.h_metrics = hhea->number_Of_HMetrics;
    f.hmtx = raw_table(f.face, TTAG_hmtx);
    f.loca = raw_table(f.face, TTAG_loca);
    if (f.loca.empty() || f.hmtx.empty() || f.h_metrics == 0)
        throw std::runtime_error("a font without TrueType outlines (no loca, hmtx or glyf)");
    f.ascii_map = f.charmap_of({1, 3, 0});
    f.unicode_map = f.charmap_of({0, 3, 1});
}

TtfFont::~TtfFont() {
    if (impl_->face) FT_Done_Face(impl_->face);
    if (impl_->library) FT_Done_FreeType(impl_->library);
}

unsigned TtfFont::glyph_index(uint32_t code, bool unicode_strings) const {
    FT_CharMap map = unicode_strings ? impl_->unicode_map : impl_->ascii_map;
    if (!map || FT_Set_Charmap(impl_->face, map) != 0) return 0;
    return FT_Get_Char_Index(impl_->face, code);
}

FontGlyph TtfFont::glyph(unsigned index) const {
    const Impl& f = *impl_;
    FontGlyph g;
    const unsigned metric = std::min(index, f.h_metrics - 1);
    g.advance = u16(f.hmtx, 4 * size_t(metric)) * f.per_unit;
    g.left_bearing = (index < f.h_metrics ? s16(f.hmtx, 4 * size_t(index) + 2)
                                          : s16(f.hmtx, 4 * size_t(f.h_metrics) +
                                                            2 * size_t(index - f.h_metrics))) *
                     f.per_unit;
    g.x_min = f.x_min(index);
    if (FT_Load_Glyph(f.face, index, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP))
        return g;  // unreadable glyph data: a blank glyph
    const FT_Outline& outline = f.face->glyph->outline;
    if (f.face->glyph->format != FT_GLYPH_FORMAT_OUTLINE) return g;
    for (int i = 0; i < outline.n_points; ++i) {
        const FT_Vector& v = outline.points[i];
        g.points.push_back({{v.x * f.per_unit, v.y * f.per_unit},
                            FT_CURVE_TAG(outline.tags[i]) == FT_CURVE_TAG_ON});
    }
    for (int c = 0; c < outline.n_contours; ++c) g.contour_ends.push_back(outline.contours[c] + 1);
    return g;
}

double TtfFont::kerning(unsigned left, unsigned right) const {
    FT_Vector k{0, 0};
    if (!FT_HAS_KERNING(impl_->face) ||
        FT_Get_Kerning(impl_->face, left, right, FT_KERNING_UNSCALED, &k) != 0)
        return 0;
    return std::max(k.x * impl_->per_unit, -1.0);
}

}  // namespace lumen::interp
