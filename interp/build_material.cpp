// material { [Ident] texture interior_texture interior modifiers }. Transforms are applied to
// the textures here, so MaterialValue::transform is only a record of them.
#include "interp/build_common.hpp"

namespace lumen::interp {

MaterialValue build_material(ItemCursor& cur) {
    static const std::vector<std::string> keywords = {"texture", "interior_texture", "interior",
                                                      "translate", "rotate", "scale", "matrix",
                                                      "transform"};
    MaterialValue m;
    if (cur.next_is<std::shared_ptr<const MaterialValue>>())
        m = *cur.next().value.as<std::shared_ptr<const MaterialValue>>();
    while (!cur.at_end()) {
        const Item& item = cur.next();
        scene::Transform t;
        if (read_transform(cur, item, t)) {
            m.texture = transformed(m.texture, t);
            m.interior_texture = transformed(m.interior_texture, t);
            m.transform = m.transform.then(t);
        } else if (item.kind == Item::Kind::Value &&
                   item.value.is<std::shared_ptr<const TextureValue>>()) {
            const auto& layers = item.value.as<std::shared_ptr<const TextureValue>>()->layers;
            m.texture.insert(m.texture.end(), layers.begin(), layers.end());
        } else if (const BlockValue* b = block_of(item, "interior_texture")) {
            ItemCursor sub(cur.ctx(), *b);
            scene::LayeredTexture layers = build_texture(sub);
            m.interior_texture.insert(m.interior_texture.end(), layers.begin(), layers.end());
        } else if (item.kind == Item::Kind::Value &&
                   item.value.is<std::shared_ptr<const scene::Interior>>()) {
            m.interior = *item.value.as<std::shared_ptr<const scene::Interior>>();
        } else {
            cur.fail_unexpected(item, keywords);
        }
    }
    return m;
}

}  // namespace lumen::interp
