// Patterns and colour maps in the scene dump: the kind's name from the pattern table, its
// parameters (`fields`) where they differ from the defaults, and the transforms and warps.
#include "interp/dump_pattern.hpp"

#include <variant>

namespace lumen::interp::dump {

namespace {

template <class... F> struct Overloaded : F... { using F::operator()...; };
template <class... F> Overloaded(F...) -> Overloaded<F...>;

std::string pattern_name(scene::PatternType t) {
    const std::string_view k = scene::pattern_info(t).keyword;
    return k.empty() ? "plain" : std::string(k);
}

const char* wave_name(scene::WaveType w) {
    static const char* names[] = {"ramp", "sine", "triangle", "scallop", "cubic", "poly"};
    return names[static_cast<int>(w)];
}

// The parameters of a pattern kind or warp (their `fields`), printed where they differ from
// the defaults.
using Field = std::variant<double, bool, glm::dvec2, glm::dvec3, std::vector<double>, std::string>;
template <class K> std::vector<std::pair<const char*, Field>> fields_of(const K& k) {
    std::vector<std::pair<const char*, Field>> out;
    K::fields(k, [&](const char* name, const auto& v) {
        using V = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<V, int>) out.emplace_back(name, double(v));
        else if constexpr (std::is_same_v<V, fn::ProgramPtr>)  // a compiled function's size
            out.emplace_back(name, Field(v ? std::to_string(v->code.size()) + " instructions" : ""));
        else out.emplace_back(name, Field(v));
    });
    return out;
}
Json field_json(const Field& f) {
    return std::visit(Overloaded{[](double v) { return Json::num(v); },
                                 [](bool v) { return Json::boolean(v); },
                                 [](const glm::dvec2& v) {
                                     return Json::array().push(Json::num(v.x)).push(Json::num(v.y));
                                 },
                                 [](const glm::dvec3& v) { return vec(v); },
                                 [](const std::vector<double>& v) {
                                     Json a = Json::array();
                                     for (double x : v) a.push(Json::num(x));
                                     return a;
                                 },
                                 [](const std::string& v) { return Json::str(v); }},
                      f);
}
template <class K> void put_fields(Json& o, const K& k) {
    const auto now = fields_of(k), def = fields_of(K{});
    for (size_t i = 0; i < now.size(); ++i)
        if (now[i].second != def[i].second) o.put(now[i].first, field_json(now[i].second));
}

const char* warp_name(const scene::warp::Mapping& m) {
    static const char* names[] = {"cylindrical", "spherical", "toroidal", "planar", "cubic"};
    return names[static_cast<int>(m.shape)];
}

// The transforms and warps in order, printed when the pattern has warps; otherwise the
// composed transform alone ("transform") describes it.
Json steps(const scene::PatternSteps& s) {
    Json a = Json::array();
    for (const scene::PatternStep& step : s.steps) {
        Json o;
        std::visit(Overloaded{[&](const scene::Transform& t) { o.put("transform", transform(t)); },
                              [](const scene::warp::ClassicTurbulence&) {},  // "turbulence"
                              [&](const scene::warp::Turbulence& t) {
                                  o.put("warp", Json::str("turbulence"));
                                  put_fields(o, t);
                              },
                              [&](const scene::warp::Repeat& r) {
                                  o.put("warp", Json::str("repeat"));
                                  put_fields(o, r);
                              },
                              [&](const scene::warp::BlackHole& b) {
                                  o.put("warp", Json::str("black_hole"));
                                  put_fields(o, b);
                              },
                              [&](const scene::warp::Mapping& m) {
                                  o.put("warp", Json::str(warp_name(m)));
                                  put_fields(o, m);
                              }},
                   step);
        if (!o.empty()) a.push(o);
    }
    return a;
}

}  // namespace

Json pattern(const scene::Pattern& p) {
    const scene::Pattern d;
    Json o;
    if (p.type() != d.type()) o.put("type", Json::str(pattern_name(p.type())));
    std::visit([&](const auto& k) { put_fields(o, k); }, p.kind);
    put_if(o, "frequency", p.frequency, d.frequency);
    put_if(o, "phase", p.phase, d.phase);
    if (p.wave != d.wave) o.put("wave", Json::str(wave_name(p.wave)));
    put_if(o, "wave_exponent", p.wave_exponent, d.wave_exponent);
    if (const scene::TurbulenceParams* t = p.steps.classic_turbulence()) put_fields(o, *t);
    put_if(o, "noise_generator", double(p.noise_generator), double(d.noise_generator));
    put_if(o, "uv_mapping", p.uv_mapping, d.uv_mapping);
    if (!p.is_plain()) {  // a plain pigment's transforms are unused
        if (p.steps.has_warps()) o.put("steps", steps(p.steps));
        else put_transform(o, p.steps.composed_transform());
    }
    if (p.unsupported) o.put("unsupported", unsupported_text(*p.unsupported));
    return o;
}

Json colour_map(const scene::ColourMap& m) {
    Json a = Json::array();
    for (const auto& e : m) {
        Json row = Json::array().push(Json::num(e.value));
        for (double v : {e.item.r, e.item.g, e.item.b, e.item.f, e.item.t})
            row.push(Json::num(v));
        a.push(row);
    }
    return a;
}

}  // namespace lumen::interp::dump
