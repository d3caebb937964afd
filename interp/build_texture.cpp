// texture { [Ident] pigment finish normal | pattern (texture_map | texture list) modifiers }
#include "interp/build_common.hpp"

namespace lumen::interp {

namespace {

const std::vector<std::string>& texture_keywords() {
    static const std::vector<std::string> k = [] {
        std::vector<std::string> v = pattern_keywords();
        for (const char* w : {"pigment", "finish", "normal", "texture_map", "quick_color",
                              "quick_colour"})
            v.push_back(w);
        return v;
    }();
    return k;
}

// `checker texture{A} texture{B}`: entry i has value i.
void read_list_form(ItemCursor& cur, scene::Texture& tex) {
    int n = pattern_list_size(tex.pattern.type());
    for (int i = 0; i < n && cur.next_is<std::shared_ptr<const TextureValue>>(); ++i) {
        tex.texture_map.push_back(
            {double(i), cur.next().value.as<std::shared_ptr<const TextureValue>>()->layers});
        tex.list_form = true;
    }
}

template <class T> bool take(ItemCursor& cur, const Item& item, const char* keyword,
                             const char* desc, T& out) {
    if (item.kind == Item::Kind::Value && item.value.is<T>()) {
        out = item.value.as<T>();
        return true;
    }
    if (item.kind == Item::Kind::Keyword && item.keyword == keyword) {
        out = cur.expect<T>(keyword, desc);
        return true;
    }
    return false;
}

}  // namespace

std::shared_ptr<scene::Texture> default_texture(const BuildContext& ctx, SourceLoc loc) {
    auto t = std::make_shared<scene::Texture>();
    t->pigment = ctx.default_pigment;
    t->finish = ctx.default_finish;
    t->normal = ctx.default_normal;
    t->loc = loc;
    return t;
}

scene::LayeredTexture build_texture(ItemCursor& cur) {
    scene::LayeredTexture below;  // lower layers of a copied layered texture
    scene::Texture top = *default_texture(cur.ctx(), cur.block_loc());
    if (cur.next_is<std::shared_ptr<const TextureValue>>()) {
        below = cur.next().value.as<std::shared_ptr<const TextureValue>>()->layers;
        if (!below.empty()) {
            top = *below.back();
            below.pop_back();
        }
    }
    top.loc = cur.block_loc();
    read_leading_uv_mapping(cur, top.pattern);
    while (!cur.at_end()) {
        const Item& item = cur.next();
        scene::Transform t;
        if (read_transform(cur, item, t)) {
            below = transformed(below, t);
            transform_own(top, t);
            continue;
        }
        scene::FinishPtr finish;
        if (take(cur, item, "finish", "a finish", finish)) {
            top.finish = apply_finish(top.finish, finish);
            continue;
        }
        if (item.kind == Item::Kind::Value && item.value.is<scene::PigmentPtr>()) {
            top.pigment = edit_pigment(cur.ctx(), item.value, top.pigment);
            continue;
        }
        if (item.kind == Item::Kind::Value && item.value.is<scene::NormalPtr>()) {
            top.normal = edit_normal(cur.ctx(), item.value, top.normal);
            continue;
        }
        if (take(cur, item, "pigment", "a pigment", top.pigment) ||
            take(cur, item, "normal", "a normal", top.normal))
            continue;
        std::shared_ptr<const TextureMapValue> map;
        if (take(cur, item, "texture_map", "a texture_map", map)) {
            top.texture_map = map->entries;
            continue;
        }
        if (item.kind == Item::Kind::Keyword &&
            (item.keyword == "quick_color" || item.keyword == "quick_colour")) {
            cur.expect_colour(item.keyword);  // preview colour: ignored
            continue;
        }
        if (const BlockValue* b = block_of(item, "tiles")) {
            // POV-Ray 3.0's `tiles { texture{A} tile2 texture{B} }`: `checker` of the two,
            // B where checker puts its first entry (measured).
            std::vector<Item> items;
            for (const Item& it : b->items)
                if (it.kind != Item::Kind::Keyword || it.keyword != "tile2") items.push_back(it);
            ItemCursor tiles(cur.ctx(), items, "tiles", b->loc);
            Item checker;
            checker.kind = Item::Kind::Keyword;
            checker.keyword = "checker";
            checker.loc = b->loc;
            read_pattern_keyword(tiles, checker, top.pattern, "texture");
            read_list_form(tiles, top);
            if (!tiles.at_end()) tiles.fail_unexpected(tiles.next(), {"texture", "tile2"});
            if (top.texture_map.size() == 2)
                std::swap(top.texture_map[0].item, top.texture_map[1].item);
            continue;
        }
        std::vector<scene::LayeredTexture> materials;
        if (read_image_block(cur, item, top.pattern, "texture", &materials)) {
            // material_map: its textures are the entries 0, 1, ... the pixel's index picks.
            top.texture_map.clear();
            for (size_t i = 0; i < materials.size(); ++i)
                top.texture_map.push_back({double(i), std::move(materials[i])});
            top.list_form = true;
            continue;
        }
        if (read_pattern_keyword(cur, item, top.pattern, "texture")) {
            if (is_list_pattern_word(item)) read_list_form(cur, top);
            if (const BlockValue* b = block_of(item, "object")) {
                ObjectEntries list(cur, *b);
                read_list_form(list.entries, top);
                list.finish();
            }
            continue;
        }
        cur.fail_unexpected(item, texture_keywords());
    }
    verify_pattern(cur, cur.here(), top.pattern);
    below.push_back(std::make_shared<scene::Texture>(std::move(top)));
    return below;
}

}  // namespace lumen::interp
