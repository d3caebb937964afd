// Pattern types and pattern modifiers shared by pigment, normal and texture blocks.
#include <glm/geometric.hpp>

#include "interp/build_common.hpp"

namespace lumen::interp {

using scene::PatternType;

namespace {

struct PatternName {
    const char* word;
    PatternType type;
    bool supported;
};

const PatternName kPatterns[] = {
    {"checker", PatternType::Checker, true},     {"gradient", PatternType::Gradient, true},
    {"planar", PatternType::Planar, true},       {"radial", PatternType::Radial, true},
    {"onion", PatternType::Onion, true},         {"spherical", PatternType::Spherical, true},
    {"cylindrical", PatternType::Cylindrical, true}, {"brick", PatternType::Brick, true},
    {"boxed", PatternType::Boxed, true},         {"hexagon", PatternType::Hexagon, true},
    {"square", PatternType::Square, true},       {"triangular", PatternType::Triangular, true},
    // noise-based: recorded, rendered once noise lands
    {"agate", PatternType::Agate, false},        {"bozo", PatternType::Bozo, false},
    {"bumps", PatternType::Bumps, false},        {"crackle", PatternType::Crackle, false},
    {"dents", PatternType::Dents, false},        {"granite", PatternType::Granite, false},
    {"leopard", PatternType::Leopard, false},    {"marble", PatternType::Marble, false},
    {"ripples", PatternType::Ripples, false},    {"spotted", PatternType::Spotted, false},
    {"waves", PatternType::Waves, false},        {"wood", PatternType::Wood, false},
    {"wrinkles", PatternType::Wrinkles, false},  {"quilted", PatternType::Quilted, false},
    // other reserved pattern words
    {"aoi", PatternType::Other, false},          {"average", PatternType::Other, false},
    {"cells", PatternType::Other, false},        {"cubic", PatternType::Other, false},
    {"julia", PatternType::Other, false},        {"mandel", PatternType::Other, false},
    {"magnet", PatternType::Other, false},       {"pavement", PatternType::Other, false},
    {"slope", PatternType::Other, false},        {"spiral1", PatternType::Other, false},
    {"spiral2", PatternType::Other, false},      {"tiling", PatternType::Other, false},
    {"facets", PatternType::Other, false},       {"function", PatternType::Other, false},
    {"density_file", PatternType::Other, false},
};

const PatternName* find_pattern(const std::string& w) {
    for (const PatternName& p : kPatterns)
        if (w == p.word) return &p;
    return nullptr;
}

// Modifiers whose effect lumen does not model; their arguments are read and dropped.
bool skip_ignored_modifier(ItemCursor& cur, const std::string& w) {
    if (w == "noise_generator" || w == "agate_turb" || w == "metric" || w == "offset" ||
        w == "control0" || w == "control1" || w == "accuracy" || w == "exponent" ||
        w == "interpolate" || w == "coords" || w == "size") {
        cur.expect_float(w);
        return true;
    }
    if (w == "interior" || w == "exterior") {  // fractal patterns: type, factor
        cur.expect_float(w);
        cur.expect_float(w);
        return true;
    }
    return w == "solid";
}

}  // namespace

void mark_unsupported(scene::Pattern& pattern, const std::string& feature, SourceLoc loc) {
    if (!pattern.unsupported) pattern.unsupported = scene::Unsupported{feature, loc};
}

int pattern_list_size(PatternType type) {
    switch (type) {
        case PatternType::Checker: case PatternType::Brick: return 2;
        case PatternType::Hexagon: return 3;
        case PatternType::Square: return 4;
        case PatternType::Triangular: return 6;
        default: return 0;
    }
}

bool is_list_pattern_word(const Item& item) {
    if (item.kind != Item::Kind::Keyword) return false;
    const PatternName* p = find_pattern(item.keyword);
    return p && pattern_list_size(p->type) > 0;
}

bool is_pattern_word(const Item& item) {
    return item.kind == Item::Kind::Keyword && find_pattern(item.keyword);
}

const std::vector<std::string>& pattern_keywords() {
    static const std::vector<std::string> k = [] {
        std::vector<std::string> v;
        for (const PatternName& p : kPatterns) v.push_back(p.word);
        for (const char* w : {"brick_size", "mortar", "frequency", "phase", "ramp_wave",
                              "sine_wave", "triangle_wave", "scallop_wave", "cubic_wave",
                              "poly_wave", "turbulence", "octaves", "omega", "lambda",
                              "uv_mapping", "noise_generator", "warp"})
            v.push_back(w);
        for (const std::string& t : transform_keywords()) v.push_back(t);
        return v;
    }();
    return k;
}

bool read_pattern_keyword(ItemCursor& cur, const Item& kw, scene::Pattern& pattern,
                          const std::string& owner) {
    scene::Transform t;
    if (read_transform(cur, kw, t)) {
        pattern.transform = pattern.transform.then(t);
        return true;
    }
    if (kw.kind == Item::Kind::Value && kw.value.is<scene::Unsupported>()) {  // warp{} ...
        mark_unsupported(pattern, kw.value.as<scene::Unsupported>().feature, kw.loc);
        return true;
    }
    if (kw.kind == Item::Kind::Value && (kw.value.is<std::shared_ptr<const FunctionValue>>() ||
                                         kw.value.is<scene::ObjectPtr>())) {
        pattern.type = PatternType::Other;  // function { } / object { } patterns
        mark_unsupported(pattern, "pattern '" + std::string(kw.value.is<scene::ObjectPtr>()
                                                                ? "object" : "function") + "'",
                         kw.loc);
        return true;
    }
    if (kw.kind != Item::Kind::Keyword) return false;
    const std::string& w = kw.keyword;
    if (const PatternName* p = find_pattern(w)) {
        pattern.type = p->type;
        if (p->type == PatternType::Gradient) {
            glm::dvec3 g = cur.expect_vector(w);
            if (glm::length(g) == 0.0) cur.fail(kw.loc, "gradient vector is zero");
            pattern.gradient = glm::normalize(g);
        }
        if (p->type == PatternType::Other) {  // mandel 25, julia <c> 30, density_file df3 "f"
            cur.accept_keyword("df3");
            while (cur.next_is_vector_like() || cur.next_is<std::string>()) cur.next();
        }
        if (!owner.empty())
            mark_unsupported(pattern, owner + " '" + w + "'", kw.loc);
        else if (!p->supported)
            mark_unsupported(pattern, "pattern '" + w + "'", kw.loc);
        return true;
    }
    if (w == "brick_size") pattern.brick_size = cur.expect_vector(w);
    else if (w == "mortar") pattern.mortar = cur.expect_float(w);
    else if (w == "frequency") pattern.frequency = cur.expect_float(w);
    else if (w == "phase") pattern.phase = cur.expect_float(w);
    else if (w == "ramp_wave") pattern.wave = scene::WaveType::Ramp;
    else if (w == "sine_wave") pattern.wave = scene::WaveType::Sine;
    else if (w == "triangle_wave") pattern.wave = scene::WaveType::Triangle;
    else if (w == "scallop_wave") pattern.wave = scene::WaveType::Scallop;
    else if (w == "cubic_wave") pattern.wave = scene::WaveType::Cubic;
    else if (w == "poly_wave") {
        pattern.wave = scene::WaveType::Poly;
        if (auto e = cur.optional_float()) pattern.wave_exponent = *e;
    } else if (w == "turbulence") {
        pattern.turbulence = cur.expect_vector(w);
        mark_unsupported(pattern, "turbulence", kw.loc);  // needs the noise functions
    } else if (w == "octaves") pattern.octaves = cur.expect_int(w);
    else if (w == "omega") pattern.omega = cur.expect_float(w);
    else if (w == "lambda") pattern.lambda = cur.expect_float(w);
    else if (w == "uv_mapping") mark_unsupported(pattern, "uv_mapping", kw.loc);
    else if (!skip_ignored_modifier(cur, w)) return false;
    return true;
}

}  // namespace lumen::interp
