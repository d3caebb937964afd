// Object modifiers: transforms, flags, textures, interiors, clipped_by / bounded_by.
//
// Space conventions (shared with the renderer): a CSG child's `transform` is relative to its
// parent CSG (the geometry is hierarchical), while textures, interior textures, clipped_by and
// bounded_by are always complete, world-space values. Transforming an object therefore moves
// the textures and clip objects of all its descendants too.
#include "interp/build_common.hpp"

namespace lumen::interp {

namespace {

const std::vector<std::string>& modifier_keywords() {
    static const std::vector<std::string> k = [] {
        std::vector<std::string> v = transform_keywords();
        for (const char* w : {"inverse", "hollow", "no_shadow", "no_image", "no_reflection",
                              "double_illuminate", "no_radiosity", "texture", "pigment",
                              "finish", "normal", "interior", "interior_texture", "material",
                              "clipped_by", "bounded_by", "split_union", "cutaway_textures",
                              "uv_mapping", "photons", "radiosity"})
            v.push_back(w);
        return v;
    }();
    return k;
}

void transform_attachments(scene::Object& obj, const scene::Transform& t) {
    obj.texture = transformed(obj.texture, t);
    if (obj.interior)
        for (auto& m : obj.interior->media) m = transformed(m, t);
    obj.interior_texture = transformed(obj.interior_texture, t);
    for (auto& c : obj.clipped_by) c = transformed(c, t);
    for (auto& b : obj.bounded_by) b = transformed(b, t);
    if (auto* mesh = std::get_if<scene::Mesh>(&obj.shape); mesh && !mesh->textures.empty())
        for (auto& layers : mesh->textures.edit()) layers = transformed(layers, t);
    if (auto* blob = std::get_if<scene::Blob>(&obj.shape))
        for (auto& c : blob->components) c.texture = transformed(c.texture, t);
    if (auto* csg = std::get_if<scene::Csg>(&obj.shape)) {
        for (auto& child : csg->children) {
            auto copy = std::make_shared<scene::Object>(*child);
            transform_attachments(*copy, t);
            child = copy;
        }
    }
}

// Layers given after an object's `uv_mapping` are uv-mapped: evaluated at the hit's (u, v, 0)
// and out of reach of the object's transforms (POV-Ray).
scene::LayeredTexture uv_mapped(const scene::Object& obj, const scene::LayeredTexture& layers) {
    if (!obj.uv_mapping) return layers;
    scene::LayeredTexture out;
    for (const scene::TexturePtr& l : layers) {
        if (!l || l->pattern.uv_mapping) {
            out.push_back(l);
            continue;
        }
        auto copy = std::make_shared<scene::Texture>(*l);
        copy->pattern.uv_mapping = true;
        out.push_back(copy);
    }
    return out;
}

// Applies `change` to the object's top texture layer (POV: `pigment {}` written directly on
// an object modifies its texture, creating one from the defaults if needed).
template <class Change>
void change_top_texture(ItemCursor& cur, const Item& item, scene::Object& obj,
                        const Change& change) {
    if (obj.texture.empty())
        obj.texture = uv_mapped(obj, {default_texture(cur.ctx(), item.loc)});
    auto top = std::make_shared<scene::Texture>(*obj.texture.back());
    if (!top->pattern.is_plain())
        cur.fail(item.loc, "cannot add " + describe_item(item) + " to a patterned texture");
    change(*top);
    obj.texture.back() = top;
}

std::vector<scene::ObjectPtr> read_bound_objects(ItemCursor& cur, const BlockValue& block,
                                                 const scene::Object& obj) {
    // `clipped_by { bounded_by }` and `bounded_by { clipped_by }` reuse the other list.
    const char* other = block.keyword == "clipped_by" ? "bounded_by" : "clipped_by";
    ItemCursor sub(cur.ctx(), block);
    std::vector<scene::ObjectPtr> out;
    while (!sub.at_end()) {
        const Item& it = sub.next();
        if (it.kind == Item::Kind::Keyword && it.keyword == other) {
            const auto& reuse = block.keyword == "clipped_by" ? obj.bounded_by : obj.clipped_by;
            out.insert(out.end(), reuse.begin(), reuse.end());
        } else if (it.kind == Item::Kind::Value && it.value.is<scene::ObjectPtr>()) {
            out.push_back(it.value.as<scene::ObjectPtr>());
        } else if (it.kind == Item::Kind::Value && it.value.is<scene::Unsupported>()) {
            out.push_back(unsupported_object(it.value.as<scene::Unsupported>()));
        } else {
            sub.fail_unexpected(it, {other});
        }
    }
    return out;
}

bool apply_value(ItemCursor& cur, const Item& item, scene::Object& obj) {
    const Value& v = item.value;
    if (v.is<std::shared_ptr<const TextureValue>>()) {
        const auto layers = uv_mapped(obj, v.as<std::shared_ptr<const TextureValue>>()->layers);
        obj.texture.insert(obj.texture.end(), layers.begin(), layers.end());
    } else if (v.is<scene::PigmentPtr>()) {
        change_top_texture(cur, item, obj,
                           [&](scene::Texture& t) { t.pigment = edit_pigment(cur.ctx(), v, t.pigment); });
    } else if (v.is<scene::FinishPtr>()) {
        change_top_texture(cur, item, obj,
                           [&](scene::Texture& t) {
                               t.finish = apply_finish(t.finish, v.as<scene::FinishPtr>());
                           });
    } else if (v.is<scene::NormalPtr>()) {
        change_top_texture(cur, item, obj,
                           [&](scene::Texture& t) { t.normal = edit_normal(cur.ctx(), v, t.normal); });
    } else if (v.is<std::shared_ptr<const scene::Interior>>()) {
        obj.interior = *v.as<std::shared_ptr<const scene::Interior>>();
    } else if (v.is<std::shared_ptr<const MaterialValue>>()) {
        const MaterialValue& m = *v.as<std::shared_ptr<const MaterialValue>>();
        const auto texture = uv_mapped(obj, m.texture), inner = uv_mapped(obj, m.interior_texture);
        obj.texture.insert(obj.texture.end(), texture.begin(), texture.end());
        obj.interior_texture.insert(obj.interior_texture.end(), inner.begin(), inner.end());
        if (m.interior) obj.interior = m.interior;
    } else if (v.is<scene::Unsupported>()) {  // photons { }, ...
        obj.unsupported.push_back(v.as<scene::Unsupported>());
    } else if (const BlockValue* b = block_of(item)) {
        if (b->keyword == "interior_texture") {
            ItemCursor sub(cur.ctx(), *b);
            scene::LayeredTexture layers = uv_mapped(obj, build_texture(sub));
            obj.interior_texture.insert(obj.interior_texture.end(), layers.begin(), layers.end());
        } else if (b->keyword == "clipped_by") {
            // Several clipped_by blocks all clip (POV keeps every one).
            auto more = read_bound_objects(cur, *b, obj);
            obj.clipped_by.insert(obj.clipped_by.end(), more.begin(), more.end());
        } else if (b->keyword == "bounded_by") {
            obj.bounded_by = read_bound_objects(cur, *b, obj);
        } else if (b->keyword == "photons") {
            read_object_photons(cur, *b, obj);
        } else if (b->keyword != "radiosity") {  // object radiosity{importance}: sampling only
            return false;
        }
    } else {
        return false;
    }
    return true;
}

}  // namespace

void transform_object(scene::Object& obj, const scene::Transform& t) {
    obj.transform = obj.transform.then(t);
    transform_attachments(obj, t);
}

scene::ObjectPtr transformed(const scene::ObjectPtr& obj, const scene::Transform& t) {
    auto copy = std::make_shared<scene::Object>(*obj);
    transform_object(*copy, t);
    return copy;
}

bool apply_object_modifier(ItemCursor& cur, const Item& item, scene::Object& obj) {
    scene::Transform t;
    if (read_transform(cur, item, t)) {
        transform_object(obj, t);
        return true;
    }
    if (item.kind == Item::Kind::Value) return apply_value(cur, item, obj);
    if (item.kind != Item::Kind::Keyword) return false;
    const std::string& w = item.keyword;
    if (w == "inverse") obj.inverse = !obj.inverse;
    else if (w == "hollow") obj.hollow = cur.optional_bool();
    else if (w == "no_shadow") obj.no_shadow = true;
    else if (w == "no_image") obj.no_image = cur.optional_bool();
    else if (w == "no_reflection") obj.no_reflection = cur.optional_bool();
    else if (w == "double_illuminate") obj.double_illuminate = cur.optional_bool();
    else if (w == "no_radiosity") obj.no_radiosity = cur.optional_bool();
    else if (w == "split_union") obj.split_union = cur.optional_bool();
    else if (w == "uv_mapping") {
        if (!obj.texture.empty())  // as POV-Ray refuses it
            cur.fail(item.loc, "uv_mapping must be specified before the texture");
        obj.uv_mapping = true;
    } else if (w == "cutaway_textures")
        obj.unsupported.push_back({w, item.loc});
    else if (w == "texture" || w == "pigment" || w == "finish" || w == "normal" ||
             w == "interior" || w == "material") {
        if (cur.at_end()) cur.fail_expected("a " + w, w);
        const Item& value = cur.next();
        if (value.kind != Item::Kind::Value || !apply_value(cur, value, obj))
            cur.fail(value.loc, "expected a " + w + " after '" + w + "', found " +
                                    describe_item(value));
    } else return false;
    return true;
}

void fail_object_item(ItemCursor& cur, const Item& item,
                      const std::vector<std::string>& extra_keywords) {
    std::vector<std::string> known = modifier_keywords();
    known.insert(known.end(), extra_keywords.begin(), extra_keywords.end());
    cur.fail_unexpected(item, known);
}

}  // namespace lumen::interp
