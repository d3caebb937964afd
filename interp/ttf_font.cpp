// FreeType gives the outlines (FT_LOAD_NO_SCALE: the points in font units, unhinted) and the
// kerning; the horizontal metrics and the glyph header boxes, which POV-Ray reads from the
// tables directly, come from the raw hmtx, loca and glyf tables. FreeType moves a glyph's
// outline by its left bearing less its xMin (so that the origin is where hmtx puts it), which
// POV-Ray does not: that shift is undone, giving the points as the glyf table stores them.
// POV-Ray's xMin is the header's xMin or the least x of the points (control points
// included) where that is less: timrom.ttf's '*' has 70 in its header and a control point at
// 66, where POV-Ray places it at 66, and its '@' has 60 and 61, placed at 60.
#include "interp/ttf_font.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_TRUETYPE_TABLES_H
#include FT_TRUETYPE_TAGS_H

#include "base/shared_library.hpp"

namespace lumen::interp {

namespace {

// FreeType's functions lumen calls, from the library opened at the first text object
// (base/shared_library.hpp): scenes without text do not load FreeType and its codecs.
#define LUMEN_FREETYPE_FUNCTIONS(X)                                                         \
    X(FT_Init_FreeType) X(FT_Done_FreeType) X(FT_New_Face) X(FT_Done_Face)                  \
    X(FT_Get_Sfnt_Table) X(FT_Load_Sfnt_Table) X(FT_Get_CMap_Format) X(FT_Set_Charmap)      \
    X(FT_Get_Char_Index) X(FT_Load_Glyph) X(FT_Get_Kerning)

LUMEN_LIBRARY_API(FreeType, LUMEN_FREETYPE_FUNCTIONS)

// The functions; throws where the library cannot be opened or lacks one of them.
const FreeType& freetype() {
    std::string why;
    const FreeType* api = base::library_api<FreeType>(LUMEN_FREETYPE_LIBRARY, why);
    if (!api) throw std::runtime_error("FreeType cannot start: " + why);
    return *api;
}

// A raw sfnt table (empty when the font has none).
std::vector<unsigned char> raw_table(FT_Face face, FT_ULong tag) {
    FT_ULong length = 0;
    if (freetype().FT_Load_Sfnt_Table(face, tag, 0, nullptr, &length) != 0) return {};
    std::vector<unsigned char> bytes(length);
    if (length && freetype().FT_Load_Sfnt_Table(face, tag, 0, bytes.data(), &length) != 0)
        return {};
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
    // unitsPerEm. Font units are divided by it, as POV-Ray does: multiplying by its inverse
    // rounds differently, and the glyph solver's tests of tiny coefficients see the difference.
    double em = 1;
    double ems(double font_units) const { return font_units / em; }
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
                const long format = freetype().FT_Get_CMap_Format(map);
                if (map->platform_id == platform && (format == 0 || format == 4 || format == 6))
                    return map;
            }
        }
        return nullptr;
    }

    // The glyph header's xMin in font units, from loca and glyf; 0 for a glyph without data.
    int header_x_min(unsigned index) const {
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
        if (freetype().FT_Load_Sfnt_Table(face, TTAG_glyf, from, header, &length) != 0) return 0;
        return int16_t(header[2] << 8 | header[3]);
    }
};

TtfFont::TtfFont(const std::string& path) : impl_(std::make_unique<Impl>()) {
    Impl& f = *impl_;
    const FreeType& ft = freetype();
    if (ft.FT_Init_FreeType(&f.library) != 0) throw std::runtime_error("FreeType cannot start");
    if (ft.FT_New_Face(f.library, path.c_str(), 0, &f.face) != 0)
        throw std::runtime_error("not a font file FreeType can read");
    const auto* head = static_cast<const TT_Header*>(ft.FT_Get_Sfnt_Table(f.face, FT_SFNT_HEAD));
    const auto* hhea =
        static_cast<const TT_HoriHeader*>(ft.FT_Get_Sfnt_Table(f.face, FT_SFNT_HHEA));
    if (!head || !hhea || head->Units_Per_EM == 0 || !FT_IS_SFNT(f.face))
        throw std::runtime_error("not a TrueType font");
    f.em = head->Units_Per_EM;
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
    if (impl_->face) freetype().FT_Done_Face(impl_->face);
    if (impl_->library) freetype().FT_Done_FreeType(impl_->library);
}

unsigned TtfFont::glyph_index(uint32_t code, bool unicode_strings) const {
    FT_CharMap map = unicode_strings ? impl_->unicode_map : impl_->ascii_map;
    if (!map || freetype().FT_Set_Charmap(impl_->face, map) != 0) return 0;
    return freetype().FT_Get_Char_Index(impl_->face, code);
}

FontGlyph TtfFont::glyph(unsigned index) const {
    const Impl& f = *impl_;
    FontGlyph g;
    const unsigned metric = std::min(index, f.h_metrics - 1);
    const int lsb = index < f.h_metrics
                        ? s16(f.hmtx, 4 * size_t(index) + 2)
                        : s16(f.hmtx, 4 * size_t(f.h_metrics) + 2 * size_t(index - f.h_metrics));
    const int header_x_min = f.header_x_min(index);
    const int shift = header_x_min - lsb;  // undoes FreeType's
    g.advance = f.ems(u16(f.hmtx, 4 * size_t(metric)));
    g.left_bearing = f.ems(lsb);
    if (freetype().FT_Load_Glyph(f.face, index,
                                 FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP))
        return g;  // unreadable glyph data: a blank glyph
    const FT_Outline& outline = f.face->glyph->outline;
    if (f.face->glyph->format != FT_GLYPH_FORMAT_OUTLINE) return g;
    long x_min = header_x_min;
    for (int i = 0; i < outline.n_points; ++i) {
        const FT_Vector& v = outline.points[i];
        const long x = v.x + shift;
        x_min = std::min(x_min, x);
        g.points.push_back({{f.ems(double(x)), f.ems(double(v.y))},
                            FT_CURVE_TAG(outline.tags[i]) == FT_CURVE_TAG_ON});
    }
    g.x_min = f.ems(double(x_min));
    for (int c = 0; c < outline.n_contours; ++c) g.contour_ends.push_back(outline.contours[c] + 1);
    return g;
}

double TtfFont::kerning(unsigned left, unsigned right) const {
    FT_Vector k{0, 0};
    if (!FT_HAS_KERNING(impl_->face) ||
        freetype().FT_Get_Kerning(impl_->face, left, right, FT_KERNING_UNSCALED, &k) != 0)
        return 0;
    return std::max(impl_->ems(double(k.x)), -1.0);
}

}  // namespace lumen::interp
