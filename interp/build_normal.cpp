// normal { [Ident] pattern [amount] [bump_size f] [accuracy f] [no_bump_scale]
// [normal_map | slope_map | list entries] modifiers }. A normal renders when its pattern does
// as a normal (scene/normal_forms.hpp); otherwise the pattern is marked unsupported.
#include "interp/build_common.hpp"

namespace lumen::interp {

namespace {

const std::vector<std::string>& normal_keywords() {
    static const std::vector<std::string> k = [] {
        std::vector<std::string> v = pattern_keywords();
        for (const char* w : {"bump_size", "normal_map", "slope_map", "accuracy", "no_bump_scale"})
            v.push_back(w);
        return v;
    }();
    return k;
}

// POV keeps the amount and the accuracy in single precision.
double as_float(double v) { return double(float(v)); }

// A normal_map or list entries replace the slope_map and the other way round: POV keeps one
// map per normal.
void set_normal_map(scene::Normal& n, scene::NormalMap map) {
    n.normal_map = std::move(map);
    n.slope_map.clear();
}

}  // namespace

scene::NormalPtr build_normal(ItemCursor& cur, const scene::Normal* base) {
    scene::Normal n;
    if (cur.next_is<scene::NormalPtr>()) n = *cur.next().value.as<scene::NormalPtr>();
    else if (base) n = *base;
    else if (cur.ctx().default_normal) n = *cur.ctx().default_normal;
    n.loc = cur.block_loc();
    read_leading_uv_mapping(cur, n.pattern);
    if (n.pattern.uv_mapping && cur.next_is<scene::NormalPtr>()) {  // `uv_mapping N ...`
        n = *cur.next().value.as<scene::NormalPtr>();
        n.pattern.uv_mapping = true;
        n.loc = cur.block_loc();
    }
    while (!cur.at_end()) {
        const Item& item = cur.next();
        // List entries: `checker normal{A} normal{B}`, valued 0, 1, ...
        if (item.kind == Item::Kind::Value && item.value.is<std::shared_ptr<const NormalMapValue>>()) {
            set_normal_map(n, item.value.as<std::shared_ptr<const NormalMapValue>>()->entries);
            continue;
        }
        if (item.kind == Item::Kind::Value && item.value.is<scene::NormalPtr>()) {
            scene::NormalMap entries = n.normal_map;
            entries.push_back({double(entries.size()), item.value.as<scene::NormalPtr>()});
            set_normal_map(n, std::move(entries));
            continue;
        }
        if (item.kind == Item::Kind::Value && item.value.is<double>()) {  // `bumps 0.5`
            n.amount = as_float(item.value.as<double>());
            continue;
        }
        if (const BlockValue* slopes = block_of(item, "slope_map")) {
            ItemCursor body(cur.ctx(), *slopes);
            n.slope_map = build_slope_map(body);
            n.normal_map.clear();
            continue;
        }
        if (item.kind == Item::Kind::Keyword) {
            const std::string& w = item.keyword;
            if (w == "bump_size") { n.amount = as_float(cur.expect_float(w)); continue; }
            if (w == "no_bump_scale") { n.no_bump_scale = cur.optional_bool(); continue; }
            if (w == "accuracy") { n.accuracy = as_float(cur.expect_float(w)); continue; }
            if (w == "normal_map") {
                set_normal_map(n, cur.expect<std::shared_ptr<const NormalMapValue>>(w, "a normal_map")->entries);
                continue;
            }
        }
        if (read_pattern_keyword(cur, item, n.pattern, "normal")) {
            if (const auto* bump = std::get_if<scene::pattern::BumpMap>(&n.pattern.kind);
                bump && bump->bump_size_given && block_of(item, "bump_map"))
                n.amount = as_float(bump->bump_size);
            if (const BlockValue* b = block_of(item, "object")) {
                ObjectEntries list(cur, *b);  // `object { OBJ normal { A }, normal { B } }`
                scene::NormalMap entries;
                for (int i = 0; i < 2 && list.entries.next_is<scene::NormalPtr>(); ++i)
                    entries.push_back({double(i), list.entries.next().value.as<scene::NormalPtr>()});
                list.finish();
                if (!entries.empty()) set_normal_map(n, std::move(entries));
            }
            continue;
        }
        cur.fail_unexpected(item, normal_keywords());
    }
    verify_pattern(cur, cur.here(), n.pattern);
    return std::make_shared<scene::Normal>(std::move(n));
}

}  // namespace lumen::interp
