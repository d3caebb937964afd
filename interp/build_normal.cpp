// normal { [Ident] pattern [amount] [bump_size f] [normal_map] modifiers }. Normal
// perturbation is not rendered yet: every pattern marks the normal unsupported.
#include "interp/build_common.hpp"

namespace lumen::interp {

namespace {

const std::vector<std::string>& normal_keywords() {
    static const std::vector<std::string> k = [] {
        std::vector<std::string> v = pattern_keywords();
        for (const char* w : {"bump_size", "normal_map", "accuracy", "no_bump_scale"})
            v.push_back(w);
        return v;
    }();
    return k;
}

}  // namespace

scene::NormalPtr build_normal(ItemCursor& cur, const scene::Normal* base) {
    scene::Normal n;
    if (cur.next_is<scene::NormalPtr>()) n = *cur.next().value.as<scene::NormalPtr>();
    else if (base) n = *base;
    else if (cur.ctx().default_normal) n = *cur.ctx().default_normal;
    n.loc = cur.block_loc();
    while (!cur.at_end()) {
        const Item& item = cur.next();
        // Normal maps and list entries (`checker normal{A} normal{B}`, valued 0, 1, ...) are
        // kept; they render once normal patterns do (the pattern's unsupported mark).
        if (item.kind == Item::Kind::Value && item.value.is<std::shared_ptr<const NormalMapValue>>()) {
            n.normal_map = item.value.as<std::shared_ptr<const NormalMapValue>>()->entries;
            continue;
        }
        if (item.kind == Item::Kind::Value && item.value.is<scene::NormalPtr>()) {
            n.normal_map.push_back({double(n.normal_map.size()), item.value.as<scene::NormalPtr>()});
            continue;
        }
        if (item.kind == Item::Kind::Value && item.value.is<double>()) {  // `bumps 0.5`
            n.amount = item.value.as<double>();
            continue;
        }
        if (item.kind == Item::Kind::Keyword) {
            const std::string& w = item.keyword;
            if (w == "bump_size") { n.amount = cur.expect_float(w); continue; }
            if (w == "no_bump_scale") { n.no_bump_scale = cur.optional_bool(); continue; }
            if (w == "accuracy") { n.accuracy = cur.expect_float(w); continue; }
            if (w == "normal_map") {
                n.normal_map = cur.expect<std::shared_ptr<const NormalMapValue>>(w, "a normal_map")->entries;
                continue;
            }
        }
        if (read_pattern_keyword(cur, item, n.pattern, "normal")) continue;
        cur.fail_unexpected(item, normal_keywords());
    }
    return std::make_shared<scene::Normal>(std::move(n));
}

}  // namespace lumen::interp
