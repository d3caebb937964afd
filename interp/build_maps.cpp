// color_map, pigment_map, texture_map, normal_map and slope_map: lists of `[value body]`
// entries kept in the order written (POV does not sort them).
#include "interp/build_common.hpp"

namespace lumen::interp {

namespace {

// Calls `entry(value, cursor, item)` for each `[v ...]` entry. A #declared map of type M
// written inside the block is spliced in by `copy`.
template <class M, class Out, class Entry>
void read_entries(ItemCursor& cur, Out& out, bool optional_value, const Entry& entry) {
    while (!cur.at_end()) {
        const Item& it = cur.next();
        if (it.kind == Item::Kind::Value && it.value.is<std::shared_ptr<const M>>()) {
            const auto& m = it.value.as<std::shared_ptr<const M>>()->entries;
            out.insert(out.end(), m.begin(), m.end());
            continue;
        }
        if (it.kind != Item::Kind::MapEntry) cur.fail_unexpected(it, {});
        ItemCursor e(cur.ctx(), it.entry, cur.what() + " entry", it.loc);
        // Entries of `average` maps may leave out their weight: it is then 1.
        double v = e.next_is_float() || !optional_value ? e.expect_float("") : 1.0;
        entry(v, e, it);
        if (!e.at_end()) e.fail_unexpected(e.peek(), {});
    }
}

size_t count_values(const std::vector<Item>& items) {
    size_t n = 0;
    for (const Item& i : items) n += i.kind == Item::Kind::Value;
    return n;
}

}  // namespace

scene::ColourMap build_colour_map(ItemCursor& cur) {
    scene::ColourMap out;
    read_entries<ColourMapValue>(cur, out, false, [&](double v, ItemCursor& e, const Item& it) {
        // The old form `[a b colour1 colour2]` is a band from a to b.
        if (e.next_is_float() && count_values(it.entry) == 4) {
            double v2 = e.expect_float("");
            scene::Colour c1 = e.expect_colour("");
            out.push_back({v, c1});
            out.push_back({v2, e.expect_colour("")});
            return;
        }
        out.push_back({v, e.expect_colour("")});
    });
    return out;
}

scene::PigmentMap build_pigment_map(ItemCursor& cur) {
    scene::PigmentMap out;
    read_entries<PigmentMapValue>(cur, out, true, [&](double v, ItemCursor& e, const Item&) {
        out.push_back({v, build_pigment(e)});
    });
    return out;
}

Value build_density_map(ItemCursor& cur, SourceLoc loc) {
    // Entries are colours or densities: a map of colours is a colour_map, any density makes
    // it a map of densities (a pigment_map), the colours becoming solid ones.
    scene::PigmentMap out;
    bool colours = true;
    read_entries<PigmentMapValue>(cur, out, false, [&](double v, ItemCursor& e, const Item&) {
        if (e.next_is<scene::PigmentPtr>()) {
            out.push_back({v, e.next().value.as<scene::PigmentPtr>()});
            colours = false;
            return;
        }
        const SourceLoc at = e.next_loc();
        out.push_back({v, solid_pigment(e.expect_colour(""), at)});
    });
    if (!colours) return Value{std::make_shared<const PigmentMapValue>(PigmentMapValue{out}), loc};
    ColourMapValue map;
    for (const auto& entry : out) map.entries.push_back({entry.value, entry.item->colour});
    return Value{std::make_shared<const ColourMapValue>(map), loc};
}

scene::TextureMap build_texture_map(ItemCursor& cur) {
    scene::TextureMap out;
    read_entries<TextureMapValue>(cur, out, true, [&](double v, ItemCursor& e, const Item&) {
        out.push_back({v, build_texture(e)});
    });
    return out;
}

scene::NormalMap build_normal_map(ItemCursor& cur) {
    scene::NormalMap out;
    read_entries<NormalMapValue>(cur, out, true, [&](double v, ItemCursor& e, const Item&) {
        out.push_back({v, build_normal(e)});
    });
    return out;
}

scene::SlopeMap build_slope_map(ItemCursor& cur) {
    scene::SlopeMap out;
    while (!cur.at_end()) {
        const Item& it = cur.next();
        if (const BlockValue* declared = block_of(it, "slope_map")) {  // `slope_map { S }`
            ItemCursor inner(cur.ctx(), *declared);
            const scene::SlopeMap m = build_slope_map(inner);
            out.insert(out.end(), m.begin(), m.end());
            continue;
        }
        if (it.kind != Item::Kind::MapEntry) cur.fail_unexpected(it, {});
        ItemCursor e(cur.ctx(), it.entry, cur.what() + " entry", it.loc);
        // POV keeps the keys in single precision, like every map's.
        const double key = double(float(e.expect_float("")));
        const std::vector<double> hs = e.expect_vecn("");  // <height, slope>; a float f is <f, f>
        if (hs.size() > 2) e.fail(it.loc, "a slope_map entry takes <height, slope>");
        out.push_back({key, {hs[0], hs.size() > 1 ? hs[1] : hs[0]}});
        if (!e.at_end()) e.fail_unexpected(e.peek(), {});
    }
    return out;
}

}  // namespace lumen::interp
