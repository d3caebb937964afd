// Pattern types and the modifiers common to every pattern, shared by pigment, normal and
// texture blocks. The pattern keywords come from the pattern table (scene/pattern_kinds.hpp);
// kind-specific arguments and modifiers are in build_pattern_kinds.cpp, warps in
// build_warp.cpp.
#include "interp/build_common.hpp"
#include "scene/normal_forms.hpp"

namespace lumen::interp {

using scene::PatternType;

namespace {

const scene::PatternInfo* find_pattern(std::string_view w) {
    for (const scene::PatternInfo& p : scene::kPatternTable)
        if (!p.keyword.empty() && w == p.keyword) return &p;
    return nullptr;
}

// POV gives marble, wood and the spirals the triangle wave when it reads their keyword.
scene::WaveType default_wave(PatternType type) {
    const bool triangle = type == PatternType::Marble || type == PatternType::Wood ||
                          type == PatternType::Spiral1 || type == PatternType::Spiral2;
    return triangle ? scene::WaveType::Triangle : scene::WaveType::Ramp;
}

// Sets the pattern's kind and marks it unsupported where lumen does not render it (as a
// normal: scene/normal_forms.hpp).
void set_kind(scene::Pattern& pattern, scene::PatternKind kind, const std::string& word,
              const std::string& owner, SourceLoc loc) {
    pattern.kind = std::move(kind);
    pattern.wave = default_wave(pattern.type());
    const PatternType type = pattern.type();
    const bool rendered =
        owner == "normal" ? scene::normal_rendered(type) : scene::pattern_info(type).rendered;
    if (!rendered)
        mark_unsupported(pattern, (owner == "normal" ? "normal" : "pattern") + std::string(" '") + word + "'", loc);
}

// turbulence, octaves, omega, lambda: the classic turbulence (scene/pattern_steps.hpp).
bool read_turbulence_keyword(ItemCursor& cur, const Item& kw, scene::Pattern& pattern) {
    const std::string& w = kw.keyword;
    if (w != "turbulence" && w != "octaves" && w != "omega" && w != "lambda") return false;
    scene::TurbulenceParams& turb = pattern.steps.classic_turbulence();
    if (w == "turbulence") turb.amount = cur.expect_vector(w);
    else if (w == "octaves") turb.octaves = cur.expect_int(w);
    else if (w == "omega") turb.omega = single_precision(cur.expect_float(w));
    else turb.lambda = single_precision(cur.expect_float(w));
    return true;
}

// frequency, phase, the wave types and noise_generator.
bool read_common_keyword(ItemCursor& cur, const Item& kw, scene::Pattern& pattern) {
    const std::string& w = kw.keyword;
    if (w == "frequency") pattern.frequency = single_precision(cur.expect_float(w));
    else if (w == "phase") pattern.phase = single_precision(cur.expect_float(w));
    else if (w == "ramp_wave") pattern.wave = scene::WaveType::Ramp;
    else if (w == "sine_wave") pattern.wave = scene::WaveType::Sine;
    else if (w == "triangle_wave") pattern.wave = scene::WaveType::Triangle;
    else if (w == "scallop_wave") pattern.wave = scene::WaveType::Scallop;
    else if (w == "cubic_wave") pattern.wave = scene::WaveType::Cubic;
    else if (w == "poly_wave") {
        pattern.wave = scene::WaveType::Poly;
        if (auto e = cur.optional_float()) pattern.wave_exponent = single_precision(*e);
    } else if (w == "noise_generator") {
        const int g = cur.expect_int(w);
        if (g < 0 || g > 3) cur.fail(kw.loc, "noise_generator must be 0, 1, 2 or 3");
        pattern.noise_generator = g;
    } else if (w == "uv_mapping") {
        cur.fail(kw.loc, "uv_mapping must come first in its block (after an identifier)",
                 "POV-Ray reads it only there");
    } else {
        return false;
    }
    return true;
}

}  // namespace

void read_leading_uv_mapping(ItemCursor& cur, scene::Pattern& pattern) {
    while (cur.accept_keyword("uv_mapping")) pattern.uv_mapping = true;
}

void mark_unsupported(scene::Pattern& pattern, const std::string& feature, SourceLoc loc) {
    if (!pattern.unsupported) pattern.unsupported = scene::Unsupported{feature, loc};
}

int pattern_list_size(PatternType type) { return scene::discrete_entries(type); }

ObjectEntries::ObjectEntries(ItemCursor& cur, const BlockValue& block) : entries(cur.ctx(), block) {
    entries.next();  // the object, read by read_pattern_keyword
}

void ObjectEntries::finish() {
    if (!entries.at_end()) entries.fail_unexpected(entries.next(), {});
}

bool is_list_pattern_word(const Item& item) {
    if (item.kind != Item::Kind::Keyword) return false;
    const scene::PatternInfo* p = find_pattern(item.keyword);
    return p && p->entries > 0;
}

bool is_pattern_word(const Item& item) {
    return item.kind == Item::Kind::Keyword && find_pattern(item.keyword);
}

const std::vector<std::string>& pattern_keywords() {
    static const std::vector<std::string> k = [] {
        std::vector<std::string> v;
        for (const scene::PatternInfo& p : scene::kPatternTable)
            if (!p.keyword.empty()) v.emplace_back(p.keyword);
        for (const char* w : {"frequency", "phase", "ramp_wave", "sine_wave", "triangle_wave",
                              "scallop_wave", "cubic_wave", "poly_wave", "turbulence",
                              "octaves", "omega", "lambda", "uv_mapping", "noise_generator",
                              "warp"})
            v.push_back(w);
        const std::vector<std::string>& kind = pattern_kind_keywords();
        v.insert(v.end(), kind.begin(), kind.end());
        for (const std::string& t : transform_keywords()) v.push_back(t);
        return v;
    }();
    return k;
}

bool read_pattern_keyword(ItemCursor& cur, const Item& kw, scene::Pattern& pattern,
                          const std::string& owner) {
    scene::Transform t;
    if (read_transform(cur, kw, t)) {
        pattern.steps.add_transform(t);
        return true;
    }
    if (const BlockValue* warp = block_of(kw, "warp")) {
        read_warp(cur, *warp, pattern);
        return true;
    }
    if (const BlockValue* b = block_of(kw, "pigment_pattern")) {
        ItemCursor sub(cur.ctx(), *b);
        scene::pattern::PigmentPattern k;
        k.pigment = build_pigment(sub);
        set_kind(pattern, std::move(k), "pigment_pattern", owner, kw.loc);
        return true;
    }
    if (const BlockValue* b = block_of(kw, "slope")) {
        ItemCursor sub(cur.ctx(), *b);
        scene::pattern::Slope k;
        read_slope_block(sub, k);
        set_kind(pattern, std::move(k), "slope", owner, kw.loc);
        return true;
    }
    if (read_image_block(cur, kw, pattern, owner, nullptr)) return true;
    if (kw.kind == Item::Kind::Value && kw.value.is<scene::Unsupported>()) {
        // density { }, ...
        mark_unsupported(pattern, kw.value.as<scene::Unsupported>().feature, kw.loc);
        return true;
    }
    if (const BlockValue* b = block_of(kw, "object")) {
        // `object { OBJ list entries }`: the entries are read by the owner (object_entries).
        ItemCursor sub(cur.ctx(), *b);
        scene::pattern::Object k;
        const scene::Unsupported* shape = sub.next_is<scene::Unsupported>()
                                              ? &sub.next().value.as<scene::Unsupported>()
                                              : nullptr;  // a shape lumen does not render
        if (!shape) k.object = sub.expect<scene::ObjectPtr>("object", "an object");
        set_kind(pattern, std::move(k), "object", owner, kw.loc);
        if (shape) mark_unsupported(pattern, shape->feature, shape->loc);
        return true;
    }
    if (kw.kind == Item::Kind::Value && kw.value.is<std::shared_ptr<const FunctionValue>>()) {
        const FunctionValue& f = *kw.value.as<std::shared_ptr<const FunctionValue>>();
        if (f.program && f.program->params > 3)
            cur.fail(kw.loc, "a pattern function is given x, y and z: this one takes " +
                                 std::to_string(f.program->params) + " parameters");
        pattern.kind = scene::pattern::Function{f.program};
        pattern.globals = cur.ctx().pattern_globals;
        if (!f.program) mark_unsupported(pattern, "pattern 'function' (" + f.why_not + ")", kw.loc);
        return true;
    }
    if (kw.kind != Item::Kind::Keyword) return false;
    const std::string& w = kw.keyword;
    if (const scene::PatternInfo* p = find_pattern(w)) {
        set_kind(pattern, scene::make_pattern_kind(p->type), w, owner, kw.loc);
        pattern.globals = cur.ctx().pattern_globals;
        read_pattern_arguments(cur, kw, pattern);
        return true;
    }
    return read_common_keyword(cur, kw, pattern) || read_turbulence_keyword(cur, kw, pattern) ||
           read_pattern_kind_modifier(cur, kw, pattern);
}

}  // namespace lumen::interp
