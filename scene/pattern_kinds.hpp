// Every pattern kind: its own parameter struct, and one row in LUMEN_PATTERN_KINDS, the single
// list the interp's keyword recognition, the renderer's dispatch, the discrete entry counts,
// the default colour maps and the scene dump all derive from.
//
// Adding a pattern: its struct here (with `fields`, or deriving NoFields), its row, a reader
// in interp/build_pattern_kinds.cpp if it takes arguments, and `evaluate(const Kind&, p)` in
// render/ once it is rendered. A missing struct, `fields` or evaluator is a compile error.
#pragma once
#include <iterator>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "function/program.hpp"

namespace lumen::scene {

struct Pigment;  // scene/texture.hpp
struct Object;   // scene/object.hpp
struct ImageData;  // scene/image_map.hpp

namespace pattern {

// `fields(kind, f)` calls f(name, value) for each parameter, in dump order; f may mutate.
struct NoFields {
    template <class Self, class F> static void fields(Self&, F&&) {}
};

struct Plain : NoFields {};  // no pattern: a solid colour or a plain texture
struct Checker : NoFields {};
struct Gradient {
    glm::dvec3 direction{1, 0, 0};  // normalised
    template <class Self, class F> static void fields(Self& s, F&& f) { f("gradient", s.direction); }
};
struct Planar : NoFields {};
struct Radial : NoFields {};
struct Onion : NoFields {};
struct Spherical : NoFields {};
struct Cylindrical : NoFields {};
struct Brick {
    glm::dvec3 size{8, 3, 4.5};
    double mortar = 0.5;
    template <class Self, class F> static void fields(Self& s, F&& f) {
        f("brick_size", s.size);
        f("mortar", s.mortar);
    }
};
struct Boxed : NoFields {};
struct Hexagon : NoFields {};
struct Square : NoFields {};
struct Triangular : NoFields {};

// Noise-based patterns (render/patterns/noise_kinds.hpp).
struct Agate {
    double agate_turb = 1.0;
    template <class Self, class F> static void fields(Self& s, F&& f) { f("agate_turb", s.agate_turb); }
};
struct Bozo : NoFields {};
struct Cells : NoFields {};
struct Bumps : NoFields {};
struct Crackle {
    double metric = 2;
    glm::dvec3 form{-1, 1, 0};
    double offset = 0;
    bool solid = false;
    template <class Self, class F> static void fields(Self& s, F&& f) {
        f("metric", s.metric);
        f("form", s.form);
        f("offset", s.offset);
        f("solid", s.solid);
    }
};
struct Dents : NoFields {};
struct Granite : NoFields {};
struct Leopard : NoFields {};
struct Marble : NoFields {};
struct Ripples : NoFields {};
struct Spotted : NoFields {};
struct Waves : NoFields {};
struct Wood : NoFields {};
struct Wrinkles : NoFields {};
// `spiral1 N` / `spiral2 N`: N arms (POV truncates the number to an integer).
struct Spiral {
    int arms = 0;
    template <class Self, class F> static void fields(Self& s, F&& f) { f("arms", s.arms); }
};
struct Spiral1 : Spiral {};
struct Spiral2 : Spiral {};
struct Quilted {
    double control0 = 1, control1 = 1;
    template <class Self, class F> static void fields(Self& s, F&& f) {
        f("control0", s.control0);
        f("control1", s.control1);
    }
};

// Patterns lumen reads but does not model yet: the numbers, vectors and strings written after
// the keyword (`mandel 25`, `julia <0.3, 0.5> 30`, `density_file df3 "f"`) are kept as written.
struct Arguments {
    std::vector<double> numbers;  // vectors flattened
    std::string file;
    template <class Self, class F> static void fields(Self& s, F&& f) {
        f("arguments", s.numbers);
        f("file", s.file);
    }
};
// The fractal patterns iterate z <- f(z) on the point's (x, y) and colour by how the orbit
// escapes (`exterior type, factor`) or stays (`interior type, factor`).
struct Fractal {
    int iterations = 0;      // the number after the keyword
    int exponent = 2;        // mandel and julia only: 2..33
    glm::dvec2 interior{0, 1}, exterior{1, 1};
    template <class Self, class F> static void fields(Self& s, F&& f) {
        f("iterations", s.iterations);
        f("exponent", s.exponent);
        f("interior", s.interior);
        f("exterior", s.exterior);
    }
};
struct Aoi : NoFields {};  // the angle between the surface normal and the ray
// `average pigment_map | texture_map | normal_map { [weight entry] ... }`: the entries
// weighted, evaluated by the pigment, texture or normal that owns the map.
struct Average : NoFields {};
struct Cubic : NoFields {};
// `julia <c>, N`.
struct Julia : Fractal {
    glm::dvec2 c{0, 0};
    template <class Self, class F> static void fields(Self& s, F&& f) {
        Fractal::fields(s, f);
        f("julia", s.c);
    }
};
struct Mandel : Fractal {};  // `mandel N`
// `magnet 1|2 mandel N` or `magnet 1|2 julia <c>, N`.
struct Magnet : Fractal {
    int type = 1;
    bool julia = false;
    glm::dvec2 c{0, 0};  // julia form only
    template <class Self, class F> static void fields(Self& s, F&& f) {
        Fractal::fields(s, f);
        f("magnet", s.type);
        f("julia_form", s.julia);
        f("julia", s.c);
    }
};
// `pavement`: POV-Ray keeps each modifier as a byte (parser: interp/build_pattern_kinds.cpp).
struct Pavement {
    double sides = 3, tiles = 1, number = 1, exterior = 0, interior = 0, form = 0;
    template <class Self, class F> static void fields(Self& s, F&& f) {
        f("number_of_sides", s.sides);
        f("number_of_tiles", s.tiles);
        f("pattern", s.number);
        f("exterior", s.exterior);
        f("interior", s.interior);
        f("form", s.form);
    }
};
// `slope <v>` or `slope { [point_at] <v> [, lo, hi] [altitude <a> [, lo, hi]] }`: how far
// the surface normal turns towards v (or towards the point v), optionally mixed with the
// height along a; each part's range [lo, hi] stretches to [0, 1] (lo = hi: left as is).
struct Slope {
    glm::dvec3 direction{0, 1, 0};  // normalised; the point itself with point_at
    double length = 1;              // |v|: the slope's weight against the altitude's
    bool point_at = false;
    glm::dvec2 range{0, 0};
    glm::dvec3 altitude{0, 0, 0};  // normalised; 0 = no altitude
    double altitude_length = 0;
    glm::dvec2 altitude_range{0, 0};
    template <class Self, class F> static void fields(Self& s, F&& f) {
        f("slope", s.direction);
        f("length", s.length);
        f("point_at", s.point_at);
        f("range", s.range);
        f("altitude", s.altitude);
        f("altitude_length", s.altitude_length);
        f("altitude_range", s.altitude_range);
    }
};
// `tiling N`: one of POV-Ray's 27 plane tilings (lumen renders 1-24).
struct Tiling {
    int type = 1;
    template <class Self, class F> static void fields(Self& s, F&& f) { f("tiling", s.type); }
};
struct Facets : Arguments {
    double coords = 0, size = 0.1, metric = 2;
    template <class Self, class F> static void fields(Self& s, F&& f) {
        Arguments::fields(s, f);
        f("coords", s.coords);
        f("size", s.size);
        f("metric", s.metric);
    }
};
// `function { ... }` as a pattern: the compiled function at the pattern point.
struct Function {
    fn::ProgramPtr program;
    template <class Self, class F> static void fields(Self& s, F&& f) { f("program", s.program); }
};
// `pigment_pattern { pigment }`: the pigment's grey value.
struct PigmentPattern : NoFields {
    std::shared_ptr<const Pigment> pigment;
};
// `object { OBJ A, B }`: entry 1 inside the object (its own transforms applied), 0 outside.
struct Object : NoFields {
    std::shared_ptr<const scene::Object> object;
};
// The voxels of a df3 file, x fastest, then y, then z, scaled to [0, 1].
struct DensityGrid {
    int nx = 0, ny = 0, nz = 0;
    std::vector<double> values;
    double at(int x, int y, int z) const { return values[(size_t(z) * ny + y) * nx + x]; }
};
// `density_file df3 "file" [interpolate 0|1|2]` over the unit cube.
struct DensityFile {
    std::string file;  // as found on the search path
    int interpolate = 0;  // 0 nearest voxel, 1 trilinear, 2 tricubic
    std::shared_ptr<const DensityGrid> grid;  // never null once read
    template <class Self, class F> static void fields(Self& s, F&& f) {
        f("file", s.file);
        f("interpolate", s.interpolate);
    }
};

// `image_map`, `bump_map`, `material_map` and `image_pattern { [TYPE] "file" modifiers }`:
// an image wrapped around pattern space (render/patterns/image_lookup.hpp). The pixels are
// shared; the settings are listed here so that dumps and content hashes see them.
struct ImageSource {
    std::shared_ptr<const ImageData> data;  // never null once read
    std::string file;                       // as found on the search path
    int map_type = 0;     // 0 planar, 1 spherical, 2 cylindrical, 5 torus (others planar)
    int interpolate = 0;  // 0 none, 2 bilinear, 3 bicubic, 4 normalised distance
    bool once = false;    // no tiling: outside the image is off the map
    bool use_index = false, use_alpha = false;
    // `filter all F` / `transmit all T` on a true-colour image: added to every pixel.
    double filter = 0, transmit = 0;
    // `filter N, F` / `transmit N, T` on a palette image, as (0 filter | 1 transmit, N, value)
    // triples in the order written; the data holds them applied.
    std::vector<double> entry_changes;
    template <class Self, class F> static void fields(Self& s, F&& f) {
        f("file", s.file);
        f("map_type", s.map_type);
        f("interpolate", s.interpolate);
        f("once", s.once);
        f("use_index", s.use_index);
        f("use_alpha", s.use_alpha);
        f("filter", s.filter);
        f("transmit", s.transmit);
        f("entry_changes", s.entry_changes);
    }
};
struct ImageMap : ImageSource {};      // a pigment: the image's colours
struct ImagePattern : ImageSource {};  // the image's grey (or alpha) as a pattern value
// A normal: the image's grey as heights. `bump_size` inside the block sets the normal's amount.
struct BumpMap : ImageSource {
    double bump_size = 0.5;
    bool bump_size_given = false;
    template <class Self, class F> static void fields(Self& s, F&& f) {
        ImageSource::fields(s, f);
        f("bump_size", s.bump_size);
    }
};
// A texture: the pixel's palette index (or red * 255) picks one of `textures` textures.
struct MaterialMap : ImageSource {
    int textures = 0;
    template <class Self, class F> static void fields(Self& s, F&& f) {
        ImageSource::fields(s, f);
        f("textures", s.textures);
    }
};

}  // namespace pattern

// X(Kind, keyword, entries, default_map, rendered)
//   keyword: the SDL word ("" for Plain, which has none)
//   entries: the entry count of a discrete (block) pattern, whose value is an index that picks
//            a map entry and whose list form takes that many items; 0 = continuous
//   default_map: the colour map used when the scene gives none (render/default_colour_maps.cpp)
//   rendered: false = the interp reports the pattern unsupported, so the renderer never sees it
#define LUMEN_PATTERN_KINDS(X)                                  \
    X(Plain, "", 0, grey_ramp, true)                            \
    X(Checker, "checker", 2, checker, true)                     \
    X(Gradient, "gradient", 0, grey_ramp, true)                 \
    X(Planar, "planar", 0, grey_ramp, true)                     \
    X(Radial, "radial", 0, radial, true)                        \
    X(Onion, "onion", 0, grey_ramp, true)                       \
    X(Spherical, "spherical", 0, grey_ramp, true)               \
    X(Cylindrical, "cylindrical", 0, grey_ramp, true)           \
    X(Brick, "brick", 2, brick, true)                           \
    X(Boxed, "boxed", 0, grey_ramp, true)                       \
    X(Hexagon, "hexagon", 3, hexagon, true)                     \
    X(Square, "square", 4, square, true)                        \
    X(Triangular, "triangular", 6, triangular, true)            \
    X(Agate, "agate", 0, agate, true)                           \
    X(Bozo, "bozo", 0, bozo, true)                              \
    X(Bumps, "bumps", 0, grey_ramp, true)                       \
    X(Crackle, "crackle", 0, grey_ramp, true)                   \
    X(Dents, "dents", 0, grey_ramp, true)                       \
    X(Granite, "granite", 0, grey_ramp, true)                   \
    X(Leopard, "leopard", 0, grey_ramp, true)                   \
    X(Marble, "marble", 0, marble, true)                        \
    X(Ripples, "ripples", 0, grey_ramp, true)                   \
    X(Spotted, "spotted", 0, grey_ramp, true)                   \
    X(Waves, "waves", 0, grey_ramp, true)                       \
    X(Wood, "wood", 0, wood, true)                              \
    X(Wrinkles, "wrinkles", 0, grey_ramp, true)                 \
    X(Quilted, "quilted", 0, grey_ramp, true)                   \
    X(Aoi, "aoi", 0, grey_ramp, true)                           \
    X(Average, "average", 0, grey_ramp, true)                   \
    X(Cells, "cells", 0, grey_ramp, true)                       \
    X(Cubic, "cubic", 6, cubic, true)                           \
    X(Julia, "julia", 0, grey_ramp, true)                       \
    X(Mandel, "mandel", 0, mandel, true)                        \
    X(Magnet, "magnet", 0, grey_ramp, true)                     \
    X(Pavement, "pavement", 0, grey_ramp, true)                 \
    X(Slope, "slope", 0, grey_ramp, true)                       \
    X(Spiral1, "spiral1", 0, grey_ramp, true)                   \
    X(Spiral2, "spiral2", 0, grey_ramp, true)                   \
    X(Tiling, "tiling", 0, grey_ramp, true)                     \
    X(Facets, "facets", 0, grey_ramp, false)                    \
    X(Function, "function", 0, grey_ramp, true)                 \
    X(PigmentPattern, "pigment_pattern", 0, grey_ramp, true)    \
    X(Object, "object", 2, checker, true)                       \
    X(DensityFile, "density_file", 0, grey_ramp, true)          \
    X(ImageMap, "image_map", 0, grey_ramp, true)                \
    X(ImagePattern, "image_pattern", 0, grey_ramp, true)        \
    X(BumpMap, "bump_map", 0, grey_ramp, true)                  \
    X(MaterialMap, "material_map", 0, grey_ramp, true)

#define LUMEN_PATTERN_ENUM(Kind, ...) Kind,
enum class PatternType { LUMEN_PATTERN_KINDS(LUMEN_PATTERN_ENUM) };
#undef LUMEN_PATTERN_ENUM

namespace pattern_detail {
// std::variant of the kinds in table order (the row macro leaves a trailing `void`).
template <class... Done> struct KindList {};
template <class List, class... Rest> struct VariantOf;
template <class... Done> struct VariantOf<KindList<Done...>, void> {
    using type = std::variant<Done...>;
};
template <class... Done, class K, class... Rest>
struct VariantOf<KindList<Done...>, K, Rest...> : VariantOf<KindList<Done..., K>, Rest...> {};
}  // namespace pattern_detail

#define LUMEN_PATTERN_TYPE(Kind, ...) pattern::Kind,
using PatternKind =
    pattern_detail::VariantOf<pattern_detail::KindList<>,
                              LUMEN_PATTERN_KINDS(LUMEN_PATTERN_TYPE) void>::type;
#undef LUMEN_PATTERN_TYPE

// The table's row for a kind.
struct PatternInfo {
    PatternType type;
    std::string_view keyword;
    int entries;
    bool rendered;
};
template <class Kind> struct PatternTraits;
#define LUMEN_PATTERN_TRAITS(Kind, keyword, entries, map, rendered)                 \
    template <> struct PatternTraits<pattern::Kind> {                               \
        static constexpr PatternInfo info{PatternType::Kind, keyword, entries, rendered}; \
    };
LUMEN_PATTERN_KINDS(LUMEN_PATTERN_TRAITS)
#undef LUMEN_PATTERN_TRAITS

#define LUMEN_PATTERN_INFO(Kind, ...) PatternTraits<pattern::Kind>::info,
inline constexpr PatternInfo kPatternTable[] = {LUMEN_PATTERN_KINDS(LUMEN_PATTERN_INFO)};
#undef LUMEN_PATTERN_INFO

// The enum, the variant and the table list the kinds in the same order.
static_assert(std::size(kPatternTable) == std::variant_size_v<PatternKind>);
template <std::size_t... I> constexpr bool rows_in_order(std::index_sequence<I...>) {
    return ((PatternTraits<std::variant_alternative_t<I, PatternKind>>::info.type ==
             PatternType(I)) && ...);
}
static_assert(rows_in_order(std::make_index_sequence<std::variant_size_v<PatternKind>>{}));

constexpr const PatternInfo& pattern_info(PatternType type) { return kPatternTable[int(type)]; }
constexpr int discrete_entries(PatternType type) { return pattern_info(type).entries; }

// A default-valued kind of the given type.
inline PatternKind make_pattern_kind(PatternType type) {
    switch (type) {
#define LUMEN_PATTERN_MAKE(Kind, ...) \
    case PatternType::Kind: return pattern::Kind{};
        LUMEN_PATTERN_KINDS(LUMEN_PATTERN_MAKE)
#undef LUMEN_PATTERN_MAKE
    }
    return pattern::Plain{};
}

}  // namespace lumen::scene
