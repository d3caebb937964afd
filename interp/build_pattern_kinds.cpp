// The arguments that follow a pattern keyword (`gradient <v>`, `mandel 25`) and the modifiers
// that belong to one kind (`mortar`, `metric`, ...). POV-Ray 3.7 refuses a kind's modifier on
// any other kind (`gradient x metric 2`: "Keyword 'metric' can only be used in a facets or
// crackle statement"), and so does lumen; on its own kind the value is kept in the kind's
// parameters, never read and dropped.
#include <cmath>
#include <type_traits>

#include <glm/geometric.hpp>

#include "base/file_resolver.hpp"
#include "interp/build_common.hpp"
#include "interp/df3_file.hpp"
#include "scene/pavement_layouts.hpp"

namespace lumen::interp {

namespace pattern = scene::pattern;

namespace {

template <class... F> struct Overloaded : F... { using F::operator()...; };
template <class... F> Overloaded(F...) -> Overloaded<F...>;
// The fallback of a visit: a user-defined conversion, so an overload taking a base of the kind
// (pattern::Arguments for Julia) is preferred to it.
struct AnyKind {
    template <class K> AnyKind(K&) {}
};

// `density_file df3 "name"`: the file is found on the scene's search path and read now.
void read_density_file(ItemCursor& cur, const Item& kw, pattern::DensityFile& d) {
    if (!cur.accept_keyword("df3")) cur.fail_expected("'df3'", kw.keyword);
    const std::string name = cur.expect_string("df3");
    d.file = FileResolver(cur.ctx().search_path).find(name, FileResolver::Kind::DensityFile);
    if (d.file.empty()) cur.fail(cur.here(), "cannot find density file '" + name + "'");
    d.grid = read_df3(d.file, cur.here());
}

// Numbers, vectors and strings after the keyword of a kind lumen does not model yet
// (`spiral1 3`, `cells`).
void read_raw_arguments(ItemCursor& cur, pattern::Arguments& args) {
    cur.accept_keyword("df3");
    while (cur.next_is_vector_like() || cur.next_is<std::string>()) {
        if (cur.next_is<std::string>()) {
            args.file = cur.expect_string("");
            continue;
        }
        const std::vector<double> v = cur.expect_vecn("");
        args.numbers.insert(args.numbers.end(), v.begin(), v.end());
    }
}


// `magnet 1|2 mandel N` or `magnet 1|2 julia <c>, N`.
void read_magnet(ItemCursor& cur, const Item& kw, pattern::Magnet& m) {
    m.type = cur.expect_int(kw.keyword);
    if (m.type != 1 && m.type != 2) cur.fail(kw.loc, "magnet type must be 1 or 2");
    if (cur.accept_keyword("julia")) {
        m.julia = true;
        m.c = read_vector2(cur, "julia");
    } else if (!cur.accept_keyword("mandel")) {
        cur.fail_expected("'mandel' or 'julia'", kw.keyword);
    }
    m.iterations = cur.expect_int(kw.keyword);
}

// `exponent n`: POV-Ray truncates it and uses 2 for any outside 2..33.
bool read_exponent(ItemCursor& cur, const std::string& w, scene::PatternKind& kind) {
    int* e = nullptr;
    if (auto* m = std::get_if<pattern::Mandel>(&kind)) e = &m->exponent;
    else if (auto* j = std::get_if<pattern::Julia>(&kind)) e = &j->exponent;
    else return false;
    *e = cur.expect_int(w);
    if (*e < 2 || *e > 33) {
        cur.warn(cur.here(), "fractal exponent must be 2 to 33: using 2");
        *e = 2;
    }
    return true;
}

// A slope or altitude vector: its direction and length.
void read_slope_vector(ItemCursor& cur, const std::string& w, glm::dvec3& dir, double& len) {
    const glm::dvec3 v = cur.expect_vector(w);
    len = glm::length(v);
    if (len == 0) cur.fail(cur.here(), "'" + w + "' vector is zero");
    dir = v / len;
}

// An optional `, lo, hi` after a slope or altitude vector.
glm::dvec2 read_range(ItemCursor& cur, const std::string& w) {
    if (!cur.next_is_float()) return {0, 0};
    const double lo = cur.expect_float(w);
    return {lo, cur.expect_float(w)};
}

// POV-Ray's conversion of a float to a byte: truncated, then modulo 256 (258 is 2, -254 is 2).
int as_byte(double v) {
    const double n = std::trunc(v);
    return std::isfinite(n) ? int(std::fmod(std::fmod(n, 256) + 256, 256)) : 0;
}

// `tiling N`: POV-Ray keeps N as a byte (truncated, then modulo 256: 258 is 2) and refuses
// one outside 1..27.
void read_tiling(ItemCursor& cur, const Item& kw, scene::Pattern&, pattern::Tiling& t) {
    t.type = as_byte(cur.expect_float(kw.keyword));
    if (t.type < 1 || t.type > 27) cur.fail(kw.loc, "tiling number must be between 1 and 27");
}

// A kind-specific modifier's value, by the type of the parameter it sets.
template <class T> T read_value(ItemCursor& cur, const std::string& w) {
    if constexpr (std::is_same_v<T, double>) {
        return cur.expect_float(w);
    } else if constexpr (std::is_same_v<T, int>) {
        return cur.expect_int(w);
    } else if constexpr (std::is_same_v<T, glm::dvec3>) {
        return cur.expect_vector(w);
    } else if constexpr (std::is_same_v<T, glm::dvec2>) {  // fractal `interior type, factor`
        const double type = cur.expect_float(w);
        return {type, cur.expect_float(w)};
    } else {
        static_assert(std::is_same_v<T, bool>);  // a flag: `solid`
        return true;
    }
}

// The parameter `Member` of pattern kind `Kind`.
template <class Kind, auto Member> struct In {
    static bool read(ItemCursor& cur, const std::string& w, scene::PatternKind& kind) {
        Kind* k = std::get_if<Kind>(&kind);
        if (!k) return false;
        auto& field = k->*Member;
        field = read_value<std::decay_t<decltype(field)>>(cur, w);
        return true;
    }
};
// The same for a parameter POV stores in single precision.
template <class Kind, auto Member> struct SingleIn {
    static bool read(ItemCursor& cur, const std::string& w, scene::PatternKind& kind) {
        if (!In<Kind, Member>::read(cur, w, kind)) return false;
        double& field = std::get<Kind>(kind).*Member;
        field = single_precision(field);
        return true;
    }
};
// Reads the modifier into the first of `Ins` whose kind the pattern has; false if none.
template <class... Ins> bool read_in(ItemCursor& cur, const std::string& w, scene::PatternKind& kind) {
    return (Ins::read(cur, w, kind) || ...);
}

// One kind-specific modifier: the kinds it applies to and the parameter it sets in each.
struct KindModifier {
    const char* keyword;
    const char* kinds;  // for the error message: "a crackle or pavement pattern"
    bool (*read)(ItemCursor& cur, const std::string& w, scene::PatternKind& kind);
};

const KindModifier kKindModifiers[] = {
    {"brick_size", "a brick pattern", read_in<In<pattern::Brick, &pattern::Brick::size>>},
    {"mortar", "a brick pattern", read_in<In<pattern::Brick, &pattern::Brick::mortar>>},
    {"metric", "a facets or crackle pattern",
     read_in<In<pattern::Crackle, &pattern::Crackle::metric>,
             In<pattern::Facets, &pattern::Facets::metric>>},
    {"offset", "a crackle pattern", read_in<In<pattern::Crackle, &pattern::Crackle::offset>>},
    {"solid", "a crackle pattern", read_in<In<pattern::Crackle, &pattern::Crackle::solid>>},
    {"form", "a crackle or pavement pattern",
     read_in<In<pattern::Crackle, &pattern::Crackle::form>,
             In<pattern::Pavement, &pattern::Pavement::form>>},
    {"exponent", "a mandel or julia pattern", read_exponent},
    {"interior", "a mandel, julia, magnet or pavement pattern",
     read_in<In<pattern::Mandel, &pattern::Mandel::interior>,
             In<pattern::Julia, &pattern::Julia::interior>,
             In<pattern::Magnet, &pattern::Magnet::interior>,
             In<pattern::Pavement, &pattern::Pavement::interior>>},
    {"exterior", "a mandel, julia, magnet or pavement pattern",
     read_in<In<pattern::Mandel, &pattern::Mandel::exterior>,
             In<pattern::Julia, &pattern::Julia::exterior>,
             In<pattern::Magnet, &pattern::Magnet::exterior>,
             In<pattern::Pavement, &pattern::Pavement::exterior>>},
    {"number_of_sides", "a pavement pattern",
     read_in<In<pattern::Pavement, &pattern::Pavement::sides>>},
    {"number_of_tiles", "a pavement pattern",
     read_in<In<pattern::Pavement, &pattern::Pavement::tiles>>},
    {"pattern", "a pavement pattern", read_in<In<pattern::Pavement, &pattern::Pavement::number>>},
    {"control0", "a quilted pattern", read_in<In<pattern::Quilted, &pattern::Quilted::control0>>},
    {"control1", "a quilted pattern", read_in<In<pattern::Quilted, &pattern::Quilted::control1>>},
    {"agate_turb", "an agate pattern", read_in<SingleIn<pattern::Agate, &pattern::Agate::agate_turb>>},
    {"interpolate", "a density_file pattern",
     read_in<In<pattern::DensityFile, &pattern::DensityFile::interpolate>>},
    {"coords", "a facets pattern", read_in<In<pattern::Facets, &pattern::Facets::coords>>},
    {"size", "a facets pattern", read_in<In<pattern::Facets, &pattern::Facets::size>>},
};

}  // namespace

const std::vector<std::string>& pattern_kind_keywords() {
    static const std::vector<std::string> k = [] {
        std::vector<std::string> v;
        for (const KindModifier& m : kKindModifiers) v.emplace_back(m.keyword);
        return v;
    }();
    return k;
}

void read_slope_block(ItemCursor& cur, pattern::Slope& s) {
    const std::string w = "slope";
    if (cur.accept_keyword("point_at")) {
        s.point_at = true;
        s.direction = cur.expect_vector("point_at");
        s.length = glm::length(s.direction);
    } else {
        read_slope_vector(cur, w, s.direction, s.length);
    }
    s.range = read_range(cur, w);
    if (cur.accept_keyword("altitude")) {
        read_slope_vector(cur, "altitude", s.altitude, s.altitude_length);
        s.altitude_range = read_range(cur, "altitude");
    }
    if (!cur.at_end()) cur.fail_unexpected(cur.peek(), {"point_at", "altitude"});
}

void read_pattern_arguments(ItemCursor& cur, const Item& kw, scene::Pattern& pattern) {
    std::visit(Overloaded{[&](pattern::Gradient& g) {
                              const glm::dvec3 v = cur.expect_vector(kw.keyword);
                              if (glm::length(v) == 0.0) cur.fail(kw.loc, "gradient vector is zero");
                              g.direction = glm::normalize(v);
                          },
                          [&](pattern::Spiral& s) { s.arms = cur.expect_int(kw.keyword); },
                          [&](pattern::Mandel& m) { m.iterations = cur.expect_int(kw.keyword); },
                          [&](pattern::Julia& j) {
                              j.c = read_vector2(cur, kw.keyword);
                              j.iterations = cur.expect_int(kw.keyword);
                          },
                          [&](pattern::Magnet& m) { read_magnet(cur, kw, m); },
                          [&](pattern::Tiling& t) { read_tiling(cur, kw, pattern, t); },
                          [&](pattern::DensityFile& d) { read_density_file(cur, kw, d); },
                          [&](pattern::Slope& s) {
                              read_slope_vector(cur, kw.keyword, s.direction, s.length);
                          },
                          // POV-Ray skips frequency and phase for quilted unless given.
                          [&](pattern::Quilted&) { pattern.frequency = 0; },
                          [&](pattern::Arguments& a) { read_raw_arguments(cur, a); },
                          [](AnyKind) {}},  // the other kinds take no arguments
               pattern.kind);
}

// POV-Ray's checks once a pattern's modifiers are read: pavement's sides, tiles and pattern
// numbers (the layouts per number of tiles: 3 sides 1 1 1 3 4 12, 4 sides 1 1 2 5 12 35, 6
// sides 1 1 3 7 22), its exterior and interior taken modulo 3, form modulo 4 (4 sides) or 3.
void verify_pattern(ItemCursor& cur, SourceLoc at, scene::Pattern& pattern) {
    auto* p = std::get_if<pattern::Pavement>(&pattern.kind);
    if (!p) return;
    struct Sides {
        int sides, forms;
        std::vector<int> layouts;  // per number of tiles
        const char* range;
    };
    static const Sides kSides[] = {{3, 3, {1, 1, 1, 3, 4, 12}, "(1,1,1,3,4,12)"},
                                   {4, 4, {1, 1, 2, 5, 12, 35}, "(1,1,2,5,12,35)"},
                                   {6, 3, {1, 1, 3, 7, 22}, "(1,1,3,7,22)"}};
    const int sides = as_byte(p->sides), tiles = as_byte(p->tiles), number = as_byte(p->number);
    const Sides* s = nullptr;
    for (const Sides& c : kSides)
        if (c.sides == sides) s = &c;
    if (!s) cur.fail(at, "number_of_sides of pavement must be 3, 4 or 6");
    const int most = int(s->layouts.size());
    if (tiles < 1 || tiles > most)
        cur.fail(at, "number_of_tiles of pavement must be between 1 and " + std::to_string(most));
    if (number < 1 || number > s->layouts[tiles - 1])
        cur.fail(at, std::string("pattern value for pavement is out of range, max per tile: ") +
                         s->range);
    p->sides = sides;
    p->tiles = tiles;
    p->number = number;
    p->exterior = as_byte(p->exterior) % 3;
    p->interior = as_byte(p->interior) % 3;
    p->form = as_byte(p->form) % s->forms;
    if (!scene::pavement_layout(sides, tiles, number))
        mark_unsupported(pattern,
                         "pattern 'pavement number_of_sides " + std::to_string(sides) +
                             " number_of_tiles " + std::to_string(tiles) + " pattern " +
                             std::to_string(number) + "'",
                         at);
}

bool read_pattern_kind_modifier(ItemCursor& cur, const Item& kw, scene::Pattern& pattern) {
    for (const KindModifier& m : kKindModifiers) {
        if (kw.keyword != m.keyword) continue;
        if (!m.read(cur, kw.keyword, pattern.kind))
            cur.fail(kw.loc, "'" + kw.keyword + "' can only be used in " + m.kinds);
        return true;
    }
    return false;
}

}  // namespace lumen::interp
