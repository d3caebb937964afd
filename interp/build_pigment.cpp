// pigment { [Ident] colour | pattern [list] [color_map|pigment_map] modifiers }
#include "interp/build_common.hpp"

namespace lumen::interp {

namespace {

const std::vector<std::string>& pigment_keywords() {
    static const std::vector<std::string> k = [] {
        std::vector<std::string> v = pattern_keywords();
        for (const char* w : {"color", "colour", "color_map", "colour_map", "pigment_map",
                              "quick_color", "quick_colour", "rgb", "rgbf", "rgbt", "rgbft"})
            v.push_back(w);
        return v;
    }();
    return k;
}

// `checker Red, White` / `hexagon pigment{A} pigment{B} pigment{C}`: entry i has value i.
void read_list_form(ItemCursor& cur, scene::Pigment& p) {
    int n = pattern_list_size(p.pattern.type());
    std::vector<scene::PigmentPtr> pigments;
    bool all_colours = true;
    for (int i = 0; i < n; ++i) {
        if (cur.next_is<scene::PigmentPtr>()) {
            pigments.push_back(cur.next().value.as<scene::PigmentPtr>());
            all_colours = false;
        } else if (cur.next_is_colour_start()) {
            SourceLoc loc = cur.peek().loc;
            pigments.push_back(solid_pigment(cur.expect_colour(""), loc));
        } else {
            break;
        }
    }
    if (pigments.empty()) return;
    p.list_form = true;
    p.colour_map.clear();
    p.pigment_map.clear();
    for (size_t i = 0; i < pigments.size(); ++i) {
        if (all_colours) p.colour_map.push_back({double(i), pigments[i]->colour});
        else p.pigment_map.push_back({double(i), pigments[i]});
    }
}

}  // namespace

scene::PigmentPtr solid_pigment(const scene::Colour& c, SourceLoc loc) {
    auto p = std::make_shared<scene::Pigment>();
    p->colour = c;
    p->loc = loc;
    return p;
}

scene::PigmentPtr build_pigment(ItemCursor& cur, const scene::Pigment* base) {
    scene::Pigment p;
    if (cur.next_is<scene::PigmentPtr>()) p = *cur.next().value.as<scene::PigmentPtr>();
    else if (base) p = *base;
    else if (cur.ctx().default_pigment) p = *cur.ctx().default_pigment;
    p.loc = cur.block_loc();
    read_leading_uv_mapping(cur, p.pattern);
    if (p.pattern.uv_mapping && cur.next_is<scene::PigmentPtr>()) {  // `uv_mapping P ...`
        p = *cur.next().value.as<scene::PigmentPtr>();
        p.pattern.uv_mapping = true;
        p.loc = cur.block_loc();
    }
    while (!cur.at_end()) {
        if (cur.next_is_colour_start()) {
            p.pattern.kind = scene::pattern::Plain{};
            p.colour = cur.expect_colour("");
            continue;
        }
        const Item& item = cur.next();
        scene::Transform t;
        if (read_transform(cur, item, t)) {  // in uv space under uv_mapping
            p.pattern.steps.add_transform(t);
            continue;
        }
        if (item.kind == Item::Kind::Value) {
            if (item.value.is<std::shared_ptr<const ColourMapValue>>()) {
                p.colour_map = item.value.as<std::shared_ptr<const ColourMapValue>>()->entries;
                continue;
            }
            if (item.value.is<std::shared_ptr<const PigmentMapValue>>()) {
                p.pigment_map = item.value.as<std::shared_ptr<const PigmentMapValue>>()->entries;
                continue;
            }
        }
        if (item.kind == Item::Kind::Keyword) {
            const std::string& w = item.keyword;
            if (w == "color_map" || w == "colour_map") {
                p.colour_map =
                    cur.expect<std::shared_ptr<const ColourMapValue>>(w, "a color_map")->entries;
                continue;
            }
            if (w == "pigment_map") {
                p.pigment_map =
                    cur.expect<std::shared_ptr<const PigmentMapValue>>(w, "a pigment_map")->entries;
                continue;
            }
            if (w == "quick_color" || w == "quick_colour") {  // preview colour: ignored
                cur.expect_colour(w);
                continue;
            }
        }
        if (read_pattern_keyword(cur, item, p.pattern, "pigment")) {
            if (is_list_pattern_word(item)) read_list_form(cur, p);
            if (const BlockValue* b = block_of(item, "object")) {
                ObjectEntries list(cur, *b);
                read_list_form(list.entries, p);
                list.finish();
            }
            continue;
        }
        cur.fail_unexpected(item, pigment_keywords());
    }
    verify_pattern(cur, cur.here(), p.pattern);
    if (std::holds_alternative<scene::pattern::Average>(p.pattern.kind) && p.pigment_map.empty())
        cur.fail(p.loc, "an average pigment needs a pigment_map");  // as POV-Ray refuses
    return std::make_shared<scene::Pigment>(std::move(p));
}

}  // namespace lumen::interp
