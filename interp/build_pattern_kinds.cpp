// The arguments that follow a pattern keyword (`gradient <v>`, `mandel 25`) and the modifiers
// that belong to one kind (`mortar`, `metric`, ...). POV-Ray 3.7 refuses a kind's modifier on
// any other kind (`gradient x metric 2`: "Keyword 'metric' can only be used in a facets or
// crackle statement"), and so does lumen; on its own kind the value is kept in the kind's
// parameters, never read and dropped.
#include <type_traits>

#include <glm/geometric.hpp>

#include "interp/build_common.hpp"

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

// Numbers, vectors and strings after the keyword of a kind lumen does not model yet
// (`julia <0.3, 0.5> 30`, `density_file df3 "f"`).
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

// A kind-specific modifier's value, by the type of the parameter it sets.
template <class T> T read_value(ItemCursor& cur, const std::string& w) {
    if constexpr (std::is_same_v<T, double>) {
        return cur.expect_float(w);
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
    {"exponent", "a mandel or julia pattern",
     read_in<In<pattern::Mandel, &pattern::Mandel::exponent>,
             In<pattern::Julia, &pattern::Julia::exponent>>},
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

void read_pattern_arguments(ItemCursor& cur, const Item& kw, scene::Pattern& pattern) {
    std::visit(Overloaded{[&](pattern::Gradient& g) {
                              const glm::dvec3 v = cur.expect_vector(kw.keyword);
                              if (glm::length(v) == 0.0) cur.fail(kw.loc, "gradient vector is zero");
                              g.direction = glm::normalize(v);
                          },
                          [&](pattern::Spiral& s) { s.arms = cur.expect_int(kw.keyword); },
                          [&](pattern::Arguments& a) { read_raw_arguments(cur, a); },
                          [](AnyKind) {}},  // the other kinds take no arguments
               pattern.kind);
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
