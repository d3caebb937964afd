// blob { [threshold T] COMPONENT... [sturm [B]] [hierarchy [B]] OBJECT_MODIFIERS }, with the
// components POV-Ray 3.7 takes:
//   sphere { <C>, R, [strength] S  [texture/pigment/normal/finish] [transforms] }
//   cylinder { <A>, <B>, R, [strength] S  ... }
//   component S, R, <C>            (the old form: a sphere)
// A component's transforms and textures apply to it alone; the blob's modifiers to the whole
// (and to the components' textures, which move with the blob).
#include <cmath>

#include <glm/geometric.hpp>

#include "interp/build_common.hpp"

namespace lumen::interp {

namespace {

// POV-Ray bounds nothing here; lumen does, so a runaway #while gets a located error.
constexpr size_t kMaxComponents = 1'000'000;

// POV-Ray uses only the radius's square: -1 is 1, and 0 makes a component without effect.
double read_radius(ItemCursor& cur, const char* what) {
    const SourceLoc loc = cur.next_loc();
    const double r = cur.expect_float("");
    if (!std::isfinite(r)) cur.fail(loc, std::string("a blob ") + what + " component's radius is not finite");
    return std::fabs(r);
}

double read_strength(ItemCursor& cur) {
    cur.accept_keyword("strength");
    return cur.expect_float("");
}

// The modifiers a component takes: its textures and transforms, read as an object's would be
// (a pigment written alone edits a texture made from the #default one).
void read_component_modifiers(ItemCursor& cur, scene::Blob::Component& c) {
    static const std::vector<std::string> kWords = [] {
        std::vector<std::string> v = transform_keywords();
        for (const char* w : {"texture", "pigment", "normal", "finish"}) v.push_back(w);
        return v;
    }();
    scene::Object holder;  // collects the component's texture and transform
    while (!cur.at_end()) {
        const Item& item = cur.peek();
        const bool texture_value =
            item.kind == Item::Kind::Value &&
            (item.value.is<std::shared_ptr<const TextureValue>>() ||
             item.value.is<scene::PigmentPtr>() || item.value.is<scene::NormalPtr>() ||
             item.value.is<scene::FinishPtr>());
        const bool texture_word =
            item.kind == Item::Kind::Keyword &&
            (item.keyword == "texture" || item.keyword == "pigment" ||
             item.keyword == "normal" || item.keyword == "finish");
        scene::Transform t;
        const Item& taken = cur.next();
        if (read_transform(cur, taken, t)) {
            transform_object(holder, t);
        } else if (!(texture_value || texture_word) || !apply_object_modifier(cur, taken, holder)) {
            cur.fail_unexpected(taken, kWords);
        }
    }
    if (!holder.transform.is_identity()) c.transform = holder.transform;
    c.texture = std::move(holder.texture);
}

scene::Blob::Component read_sphere_component(BuildContext& ctx, const BlockValue& block) {
    ItemCursor cur(ctx, block.items, "blob sphere component", block.loc);
    scene::Blob::Component c;
    c.a = c.b = cur.expect_vector("");
    c.radius = read_radius(cur, "sphere");
    c.strength = read_strength(cur);
    read_component_modifiers(cur, c);
    return c;
}

scene::Blob::Component read_cylinder_component(BuildContext& ctx, const BlockValue& block) {
    ItemCursor cur(ctx, block.items, "blob cylinder component", block.loc);
    scene::Blob::Component c;
    c.cylinder = true;
    c.a = cur.expect_vector("");
    c.b = cur.expect_vector("");
    if (!(glm::length(c.b - c.a) > 0))
        cur.fail(block.loc, "degenerate blob cylinder component: its ends are the same point");
    c.radius = read_radius(cur, "cylinder");
    c.strength = read_strength(cur);
    read_component_modifiers(cur, c);
    return c;
}

}  // namespace

scene::ObjectPtr build_blob(ItemCursor& cur) {
    scene::Blob blob;
    // The blob's own items; POV-Ray reads them all before the object modifiers.
    auto own_item = [&](const Item& item) {  // one of the words below
        if (item.keyword == "threshold") {
            blob.threshold = cur.expect_float("threshold");
        } else if (item.keyword == "sturm") {
            blob.sturm = cur.optional_bool();
        } else if (item.keyword == "hierarchy") {
            blob.hierarchy = cur.optional_bool();
        } else if (item.keyword == "component") {
            scene::Blob::Component c;
            c.strength = cur.expect_float("component");
            c.radius = read_radius(cur, "component");
            c.a = c.b = cur.expect_vector("component");
            blob.components.push_back(c);
        }
    };
    while (!cur.at_end()) {
        const Item& item = cur.peek();
        const BlockValue* sphere = block_of(item, "sphere");
        const BlockValue* cylinder = block_of(item, "cylinder");
        const bool word = item.kind == Item::Kind::Keyword &&
                          (item.keyword == "threshold" || item.keyword == "sturm" ||
                           item.keyword == "hierarchy" || item.keyword == "component");
        if (!sphere && !cylinder && !word) break;
        const Item& taken = cur.next();
        if (sphere) blob.components.push_back(read_sphere_component(cur.ctx(), *sphere));
        if (cylinder) blob.components.push_back(read_cylinder_component(cur.ctx(), *cylinder));
        if (word) own_item(taken);
        if (blob.components.size() > kMaxComponents)
            cur.fail(taken.loc, "a blob has more than " + std::to_string(kMaxComponents) +
                                    " components");
    }
    if (blob.components.empty())
        cur.fail(cur.block_loc(), "a blob needs at least one component");
    scene::Object obj;
    obj.loc = cur.block_loc();
    obj.shape = std::move(blob);  // the modifiers move the components' textures with the blob
    read_object_modifiers(cur, obj, [&](const Item& item) {
        if (block_of(item, "sphere") || block_of(item, "cylinder"))
            cur.fail(item.loc, "a blob's components come before its object modifiers");
        if (item.kind != Item::Kind::Keyword) return false;
        scene::Blob& b = std::get<scene::Blob>(obj.shape);
        if (item.keyword == "sturm") b.sturm = cur.optional_bool();
        else if (item.keyword == "hierarchy") b.hierarchy = cur.optional_bool();
        else return false;
        return true;
    }, {"threshold", "component", "sphere", "cylinder", "sturm", "hierarchy"});
    return std::make_shared<scene::Object>(std::move(obj));
}

}  // namespace lumen::interp
