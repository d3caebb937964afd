// finish { } as POV-Ray 3.7 reads it (defaults are scene::Finish's).
#include <cmath>

#include "interp/build_common.hpp"

namespace lumen::interp {

namespace {

// Which fields a `finish { ... }` block wrote. POV applies such a block on top of the finish
// already in place (`texture { T finish { phong 1 } }` keeps T's other settings), so a finish
// built without a leading identifier remembers its fields in its deleter (std::get_deleter).
enum FinishField : uint32_t {
    kAmbient = 1u << 0, kEmission = 1u << 1, kDiffuse = 1u << 2, kDiffuseBack = 1u << 3,
    kBrilliance = 1u << 4, kPhong = 1u << 5, kPhongSize = 1u << 6, kSpecular = 1u << 7,
    kRoughness = 1u << 8, kMetallic = 1u << 9, kCrand = 1u << 10, kReflection = 1u << 11,
    kReflectionExponent = 1u << 12, kConserveEnergy = 1u << 13, kIrid = 1u << 14, kIor = 1u << 15,
};

struct FinishDelta {
    uint32_t set = 0;
    void operator()(const scene::Finish* f) const { delete f; }
};

const std::vector<std::string>& finish_keywords() {
    static const std::vector<std::string> k = {
        "ambient", "emission", "diffuse", "albedo", "brilliance", "phong", "phong_size",
        "specular", "roughness", "metallic", "crand", "reflection", "reflection_exponent",
        "conserve_energy", "irid", "ior", "refraction", "caustics", "fade_distance",
        "fade_power"};
    return k;
}

// reflection { Cmin [, Cmax] [fresnel [on]] [falloff F] [exponent E] [metallic [M]] }
void read_reflection_block(BuildContext& ctx, const BlockValue& block, scene::Finish& f) {
    ItemCursor cur(ctx, block);
    std::vector<glm::dvec3> colours;
    while (!cur.at_end()) {
        if (cur.next_is_colour_start()) {
            if (colours.size() == 2) cur.fail(cur.peek().loc, "reflection takes at most 2 colours");
            colours.push_back(cur.expect_colour("").rgb());
            continue;
        }
        const Item& item = cur.next();
        const std::string w = item.kind == Item::Kind::Keyword ? item.keyword : "";
        if (w == "fresnel") f.fresnel = cur.optional_bool();
        else if (w == "falloff") f.reflection_falloff = cur.expect_float(w);
        else if (w == "exponent") f.reflection_exponent = cur.expect_float(w);
        else if (w == "metallic") f.reflection_metallic = cur.optional_float().value_or(1.0);
        else cur.fail_unexpected(item, {"fresnel", "falloff", "exponent", "metallic"});
    }
    if (colours.empty()) cur.fail(block.loc, "reflection needs a colour");
    f.reflection_max = colours.back();
    // One colour sets both ends, except under fresnel where the minimum becomes 0.
    f.reflection_min = colours.size() == 2 ? colours[0]
                       : f.fresnel         ? glm::dvec3(0)
                                           : colours[0];
}

// irid { amount [thickness t] [turbulence t] }
void read_irid_block(BuildContext& ctx, const BlockValue& block, scene::Finish& f) {
    ItemCursor cur(ctx, block);
    f.irid_amount = cur.expect_float("");
    while (!cur.at_end()) {
        const Item& item = cur.next();
        const std::string w = item.kind == Item::Kind::Keyword ? item.keyword : "";
        if (w == "thickness") f.irid_thickness = cur.expect_float(w);
        else if (w == "turbulence") f.irid_turbulence = cur.expect_float(w);
        else cur.fail_unexpected(item, {"thickness", "turbulence"});
    }
}

}  // namespace

scene::FinishPtr apply_finish(const scene::FinishPtr& base, const scene::FinishPtr& f) {
    const FinishDelta* d = f ? std::get_deleter<FinishDelta>(f) : nullptr;
    if (!d || !base) return f;
    auto out = std::make_shared<scene::Finish>(*base);
    auto take = [&](uint32_t bit, auto member) {
        if (d->set & bit) (*out).*member = (*f).*member;
    };
    take(kAmbient, &scene::Finish::ambient);
    take(kEmission, &scene::Finish::emission);
    take(kDiffuse, &scene::Finish::diffuse);
    take(kDiffuseBack, &scene::Finish::diffuse_back);
    take(kBrilliance, &scene::Finish::brilliance);
    take(kPhong, &scene::Finish::phong);
    take(kPhongSize, &scene::Finish::phong_size);
    take(kSpecular, &scene::Finish::specular);
    take(kRoughness, &scene::Finish::roughness);
    take(kMetallic, &scene::Finish::metallic);
    take(kCrand, &scene::Finish::crand);
    take(kReflection, &scene::Finish::reflection_min);
    take(kReflection, &scene::Finish::reflection_max);
    take(kReflection, &scene::Finish::reflection_falloff);
    take(kReflection, &scene::Finish::reflection_metallic);
    take(kReflection, &scene::Finish::fresnel);
    take(kReflectionExponent | kReflection, &scene::Finish::reflection_exponent);
    take(kConserveEnergy, &scene::Finish::conserve_energy);
    take(kIrid, &scene::Finish::irid_amount);
    take(kIrid, &scene::Finish::irid_thickness);
    take(kIrid, &scene::Finish::irid_turbulence);
    take(kIor, &scene::Finish::ior);
    out->loc = f->loc;
    return out;
}

scene::FinishPtr build_finish(ItemCursor& cur) {
    scene::Finish f;
    bool delta = true;  // false when the block starts from a declared finish
    uint32_t set = 0;
    if (cur.next_is<scene::FinishPtr>()) {
        f = *cur.next().value.as<scene::FinishPtr>();
        delta = false;
    } else if (cur.ctx().default_finish) {
        f = *cur.ctx().default_finish;
    }
    f.loc = cur.block_loc();
    // `albedo` adjustments use the final brilliance/phong_size/roughness: applied at the end.
    bool diffuse_albedo = false, phong_albedo = false, specular_albedo = false;
    while (!cur.at_end()) {
        const Item& item = cur.next();
        if (const BlockValue* b = block_of(item, "reflection")) {
            set |= kReflection;
            read_reflection_block(cur.ctx(), *b, f);
            continue;
        }
        if (const BlockValue* b = block_of(item, "irid")) {
            set |= kIrid;
            read_irid_block(cur.ctx(), *b, f);
            continue;
        }
        if (item.kind == Item::Kind::Value && item.value.is<scene::Unsupported>()) {
            cur.warn(item.loc, "'" + item.value.as<scene::Unsupported>().feature +
                                   "' in a finish is not supported: ignored");
            continue;
        }
        if (item.kind != Item::Kind::Keyword) cur.fail_unexpected(item, finish_keywords());
        const std::string& w = item.keyword;
        if (w == "ambient") { f.ambient = cur.expect_colour(w).rgb(); set |= kAmbient; }
        else if (w == "emission") { f.emission = cur.expect_colour(w).rgb(); set |= kEmission; }
        else if (w == "diffuse") {
            diffuse_albedo = cur.accept_keyword("albedo");
            f.diffuse = cur.expect_float(w);
            set |= kDiffuse;
            if (auto back = cur.optional_float()) { f.diffuse_back = *back; set |= kDiffuseBack; }
        } else if (w == "brilliance") { f.brilliance = cur.expect_float(w); set |= kBrilliance; }
        else if (w == "phong") {
            phong_albedo = cur.accept_keyword("albedo");
            f.phong = cur.expect_float(w);
            set |= kPhong;
        } else if (w == "phong_size") { f.phong_size = cur.expect_float(w); set |= kPhongSize; }
        else if (w == "specular") {
            specular_albedo = cur.accept_keyword("albedo");
            f.specular = cur.expect_float(w);
            set |= kSpecular;
        } else if (w == "roughness") {
            f.roughness = cur.expect_float(w);
            if (f.roughness <= 0) cur.fail(item.loc, "roughness must be greater than 0");
            set |= kRoughness;
        } else if (w == "metallic") {
            f.metallic = cur.optional_float().value_or(1.0);
            set |= kMetallic;
        } else if (w == "crand") { f.crand = cur.expect_float(w); set |= kCrand; }
        else if (w == "reflection") {
            glm::dvec3 c = cur.expect_colour(w).rgb();
            f.reflection_min = f.reflection_max = c;
            set |= kReflection;
        } else if (w == "reflection_exponent") {
            f.reflection_exponent = cur.expect_float(w);
            set |= kReflectionExponent;
        } else if (w == "conserve_energy") {
            f.conserve_energy = cur.optional_bool();
            set |= kConserveEnergy;
        } else if (w == "ior") { f.ior = cur.expect_float(w); set |= kIor; }
        else if (w == "refraction" || w == "caustics" || w == "fade_distance" ||
                 w == "fade_power") {
            cur.expect_float(w);
            cur.warn(item.loc, "obsolete finish keyword '" + w + "' ignored (use interior)");
        } else cur.fail_unexpected(item, finish_keywords());
    }
    if (diffuse_albedo) f.diffuse *= (f.brilliance + 1.0) / 2.0;
    if (phong_albedo) f.phong *= (f.phong_size + 1.0) / 2.0;
    if (specular_albedo) {
        double e = 1.0 / f.roughness;
        f.specular *= (e + 2.0) / (4.0 * (2.0 - std::pow(2.0, -e / 2.0)));
    }
    if (!delta) return std::make_shared<scene::Finish>(std::move(f));
    return scene::FinishPtr(new scene::Finish(std::move(f)), FinishDelta{set});
}

}  // namespace lumen::interp
