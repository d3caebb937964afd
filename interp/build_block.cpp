// The builders' entry points (interp/builders.hpp): block dispatch, top-level items,
// #default, and the final list of unsupported features.
#include <algorithm>
#include <tuple>

#include "interp/build_common.hpp"

namespace lumen::interp {

namespace {

// Blocks built into typed values: the shapes of scene/shape_list.hpp, then the rest.
const std::vector<std::string> kBuilt = scene::keywords_then(scene::kShapeKeywords, {
    "object", "union", "merge", "intersection", "difference", "light_group", "texture", "pigment", "finish", "normal", "interior", "material", "camera",
    "light_source", "transform", "color_map", "colour_map", "pigment_map", "texture_map",
    "normal_map", "fog", "rainbow", "sky_sphere", "media", "density", "density_map"});
// Blocks that only mean something inside a parent: returned as BlockValue.
const std::vector<std::string> kData = {
    "reflection", "irid", "radiosity", "vertex_vectors", "normal_vectors", "uv_vectors",
    "texture_list", "face_indices", "normal_indices", "uv_indices", "clipped_by", "bounded_by",
    "looks_like", "projected_through", "global_settings", "background", "interior_texture",
    "default",   // `default { }`: the old spelling of #default
    "warp",      // read by the pattern it modifies (build_warp.cpp)
    "pigment_pattern",   // read by the pattern it makes (build_pattern.cpp)
    "slope",             // `slope { ... }` (build_pattern_kinds.cpp)
    "slope_map",         // read by its normal (build_normal.cpp)
    "mesh_camera",       // read by its camera (build_camera.cpp)
    "tiles",             // read by its texture (build_texture.cpp)
    "image_map", "image_pattern", "bump_map", "material_map",  // build_image_map.cpp
    "contained_by",      // read by its isosurface (build_isosurface.cpp)
    "scattering",        // read by its media (build_media.cpp)
    "photons"};          // global, object and light blocks (build_photons.cpp)
// Reserved block words lumen parses but does not build (the evaluator makes Unsupported):
// the unrendered shapes, then the rest.
const std::vector<std::string> kUnsupported = scene::keywords_then(scene::kUnsupportedShapeKeywords, {
    "subsurface",
    "density_file", "spline",
    "function"});

bool contains(const std::vector<std::string>& v, const std::string& s) {
    return std::find(v.begin(), v.end(), s) != v.end();
}

template <class T> Value make(const T& v, SourceLoc loc) {
    return Value{std::make_shared<const T>(v), loc};
}

// Every Unsupported reachable from a texture / pigment / normal.
void collect(const scene::PigmentPtr& p, std::vector<scene::Unsupported>& out);
void collect(const scene::ObjectPtr& o, std::vector<scene::Unsupported>& out);
void collect(const scene::Pattern& p, std::vector<scene::Unsupported>& out) {
    if (p.unsupported) out.push_back(*p.unsupported);
    if (const auto* k = std::get_if<scene::pattern::PigmentPattern>(&p.kind)) collect(k->pigment, out);
    if (const auto* k = std::get_if<scene::pattern::Object>(&p.kind)) collect(k->object, out);
}
void collect(const scene::PigmentPtr& p, std::vector<scene::Unsupported>& out) {
    if (!p) return;
    collect(p->pattern, out);
    for (const auto& e : p->pigment_map) collect(e.item, out);
}
void collect(const scene::NormalPtr& n, std::vector<scene::Unsupported>& out) {
    if (!n) return;
    collect(n->pattern, out);
    for (const auto& e : n->normal_map) collect(e.item, out);
}
void collect(const scene::LayeredTexture& layers, std::vector<scene::Unsupported>& out) {
    for (const auto& t : layers) {
        if (!t) continue;
        collect(t->pattern, out);
        collect(t->pigment, out);
        collect(t->normal, out);
        for (const auto& e : t->texture_map) collect(e.item, out);
    }
}
void collect(const scene::ObjectPtr& o, std::vector<scene::Unsupported>& out) {
    if (!o) return;
    if (const auto* u = std::get_if<scene::UnsupportedShape>(&o->shape)) out.push_back(u->what);
    out.insert(out.end(), o->unsupported.begin(), o->unsupported.end());
    collect(o->texture, out);
    collect(o->interior_texture, out);
    if (o->interior)
        for (const auto& m : o->interior->media)
            for (const auto& d : m->densities) collect(d, out);
    if (const auto* mesh = std::get_if<scene::Mesh>(&o->shape))
        for (const auto& t : mesh->textures) collect(t, out);
    if (const auto* csg = std::get_if<scene::Csg>(&o->shape))
        for (const auto& c : csg->children) collect(c, out);
    for (const auto& c : o->clipped_by) collect(c, out);
    for (const auto& c : o->bounded_by) collect(c, out);
}

}  // namespace

bool is_supported_block(const std::string& keyword) {
    return contains(kBuilt, keyword) || contains(kData, keyword);
}

bool is_pattern_owner(const std::string& keyword) {
    return keyword == "pigment" || keyword == "texture" || keyword == "normal" ||
           keyword == "density";
}

const std::vector<std::string>& known_block_keywords() {
    static const std::vector<std::string> all = [] {
        std::vector<std::string> v = kBuilt;
        v.insert(v.end(), kData.begin(), kData.end());
        v.insert(v.end(), kUnsupported.begin(), kUnsupported.end());
        return v;
    }();
    return all;
}

const BlockValue* block_of(const Item& item, std::string_view keyword) {
    if (item.kind != Item::Kind::Value || !item.value.is<std::shared_ptr<const BlockValue>>())
        return nullptr;
    const BlockValue* b = item.value.as<std::shared_ptr<const BlockValue>>().get();
    return keyword.empty() || b->keyword == keyword ? b : nullptr;
}

namespace {

// A pigment/normal block that does not start with a declared one of its kind, kept for
// edit_pigment()/edit_normal().
template <class T> std::shared_ptr<const BlockValue> edits_of(const BlockValue& block) {
    const bool copies = !block.items.empty() && block.items.front().kind == Item::Kind::Value &&
                        block.items.front().value.is<T>();
    if (copies) return nullptr;
    return std::make_shared<const BlockValue>(block);
}

}  // namespace

scene::PigmentPtr edit_pigment(BuildContext& ctx, const Value& v, const scene::PigmentPtr& current) {
    if (!v.edits || !current) return v.as<scene::PigmentPtr>();
    ItemCursor cur(ctx, *v.edits);
    return build_pigment(cur, current.get());
}

scene::NormalPtr edit_normal(BuildContext& ctx, const Value& v, const scene::NormalPtr& current) {
    if (!v.edits || !current) return v.as<scene::NormalPtr>();
    ItemCursor cur(ctx, *v.edits);
    return build_normal(cur, current.get());
}

Value build_block(BuildContext& ctx, const BlockValue& block) {
    const std::string& k = block.keyword;
    SourceLoc loc = block.loc;
    if (contains(kData, k)) return make(block, loc);
    ItemCursor cur(ctx, block);
    if (k == "texture") return make(TextureValue{build_texture(cur)}, loc);
    if (k == "pigment") return Value{build_pigment(cur), loc, edits_of<scene::PigmentPtr>(block)};
    if (k == "finish") return Value{build_finish(cur), loc};
    if (k == "normal") return Value{build_normal(cur), loc, edits_of<scene::NormalPtr>(block)};
    if (k == "interior") return make(build_interior(cur), loc);
    if (k == "material") return make(build_material(cur), loc);
    if (k == "camera") return make(build_camera(cur), loc);
    if (k == "light_source") return make(build_light(cur), loc);
    if (k == "object" && cur.next_is<std::shared_ptr<const scene::Light>>())
        return make(build_light(cur), loc);  // object { LightIdent modifiers }
    if (k == "transform") return make(build_transform_block(cur), loc);
    if (k == "color_map" || k == "colour_map") return make(ColourMapValue{build_colour_map(cur)}, loc);
    if (k == "pigment_map") return make(PigmentMapValue{build_pigment_map(cur)}, loc);
    if (k == "texture_map") return make(TextureMapValue{build_texture_map(cur)}, loc);
    if (k == "normal_map") return make(NormalMapValue{build_normal_map(cur)}, loc);
    if (k == "fog") return make(build_fog(cur), loc);
    if (k == "rainbow") return make(build_rainbow(cur), loc);
    if (k == "media") return Value{build_media(cur), loc};
    if (k == "density") return Value{build_density(cur), loc};
    if (k == "density_map") return build_density_map(cur, loc);
    if (k == "sky_sphere") return make(build_sky_sphere(cur), loc);
    if (contains(kBuilt, k)) return Value{build_object(cur), loc};
    throw LumenError(loc, "'" + k + "' is not supported yet");
}

void apply_top_level(BuildContext& ctx, scene::Scene& scene, const Item& item) {
    if (item.kind != Item::Kind::Value) {
        if (item.kind == Item::Kind::Comma || item.kind == Item::Kind::MapEntry)
            throw LumenError(item.loc, "unexpected " + describe_item(item) + " at top level");
        throw LumenError(item.loc, "unexpected '" + item.keyword + "' at top level");
    }
    const Value& v = item.value;
    if (v.is<scene::ObjectPtr>()) {
        scene::ObjectPtr obj = v.as<scene::ObjectPtr>();
        // POV gives an object without a texture the #default texture in effect where the
        // object is placed in the scene, not where it was declared (CSG children without a
        // texture inherit it).
        if (obj->texture.empty() && (ctx.default_pigment || ctx.default_finish || ctx.default_normal)) {
            auto textured = std::make_shared<scene::Object>(*obj);
            textured->texture.push_back(default_texture(ctx, obj->loc));
            obj = textured;
        }
        scene.objects.push_back(place_csg_lights(obj, scene::Transform{}, scene));
    } else if (v.is<std::shared_ptr<const scene::Camera>>()) {
        scene.camera = *v.as<std::shared_ptr<const scene::Camera>>();
    } else if (v.is<std::shared_ptr<const scene::Light>>()) {
        scene.lights.push_back(*v.as<std::shared_ptr<const scene::Light>>());
    } else if (v.is<std::shared_ptr<const scene::Fog>>()) {
        scene.fogs.push_back(*v.as<std::shared_ptr<const scene::Fog>>());
    } else if (v.is<std::shared_ptr<const scene::Rainbow>>()) {
        scene.rainbows.push_back(*v.as<std::shared_ptr<const scene::Rainbow>>());
    } else if (v.is<scene::MediaPtr>()) {
        scene.atmosphere.push_back(v.as<scene::MediaPtr>());
    } else if (v.is<std::shared_ptr<const scene::SkySphere>>()) {
        scene.sky_sphere = *v.as<std::shared_ptr<const scene::SkySphere>>();
    } else if (v.is<scene::Unsupported>()) {
        const scene::Unsupported& u = v.as<scene::Unsupported>();
        if (is_unsupported_shape(u.feature)) scene.objects.push_back(unsupported_object(u));
        else scene.globals.unsupported.push_back(u);  // atmospheric media, ...
    } else if (const BlockValue* b = block_of(item, "global_settings")) {
        ItemCursor cur(ctx, *b);
        apply_global_settings(cur, scene.globals);
    } else if (const BlockValue* b = block_of(item, "default")) {
        apply_default(ctx, *b);
    } else if (const BlockValue* b = block_of(item, "background")) {
        ItemCursor cur(ctx, *b);
        scene.background = build_background(cur);
    } else {
        throw LumenError(item.loc, describe_value(v) + " cannot stand at top level");
    }
}

void apply_default(BuildContext& ctx, const BlockValue& block) {
    ItemCursor cur(ctx, block);
    while (!cur.at_end()) {
        const Item& item = cur.next();
        const Value& v = item.value;
        if (item.kind != Item::Kind::Value) cur.fail_unexpected(item, {"texture", "pigment", "finish", "normal"});
        if (v.is<std::shared_ptr<const TextureValue>>()) {
            const auto& layers = v.as<std::shared_ptr<const TextureValue>>()->layers;
            if (layers.empty()) continue;
            ctx.default_pigment = layers.back()->pigment;
            ctx.default_finish = layers.back()->finish;
            ctx.default_normal = layers.back()->normal;
        } else if (v.is<scene::PigmentPtr>()) {
            ctx.default_pigment = v.as<scene::PigmentPtr>();
        } else if (v.is<scene::FinishPtr>()) {
            ctx.default_finish = v.as<scene::FinishPtr>();
        } else if (v.is<scene::NormalPtr>()) {
            ctx.default_normal = v.as<scene::NormalPtr>();
        } else {
            cur.fail_unexpected(item, {"texture", "pigment", "finish", "normal"});
        }
    }
}

void finish_scene(BuildContext& ctx, scene::Scene& scene) {
    // Without global_settings { noise_generator }, POV uses the original noise for scenes
    // whose final #version is below 3.5.
    scene::GlobalSettings& g = scene.globals;
    if (!ctx.noise_generator_given && scene.language_version < 3.5) g.noise_generator = 1;
    *ctx.pattern_globals = {g.noise_generator, g.number_of_waves};
    std::vector<scene::Unsupported> out;
    for (const auto& o : scene.objects) collect(o, out);
    if (scene.camera.unsupported) out.push_back(*scene.camera.unsupported);
    for (const auto& l : scene.lights) {
        out.insert(out.end(), l.unsupported.begin(), l.unsupported.end());
        collect(l.looks_like, out);
        collect(l.projected_through, out);
    }
    for (const auto& f : scene.fogs)
        if (f.unsupported) out.push_back(*f.unsupported);
    for (const auto& m : scene.atmosphere)
        for (const auto& d : m->densities) collect(d, out);
    if (scene.sky_sphere)
        for (const auto& p : scene.sky_sphere->pigments) collect(p, out);
    out.insert(out.end(), scene.globals.unsupported.begin(), scene.globals.unsupported.end());
    // Source order (by file name, then offset); a declared texture used twice counts once.
    auto key = [](const scene::Unsupported& u) {
        return std::make_tuple(u.loc.file ? u.loc.file->name : std::string(), u.loc.byte,
                               u.feature);
    };
    std::stable_sort(out.begin(), out.end(),
                     [&](const auto& a, const auto& b) { return key(a) < key(b); });
    out.erase(std::unique(out.begin(), out.end(),
                          [&](const auto& a, const auto& b) { return key(a) == key(b); }),
              out.end());
    scene.unsupported = std::move(out);
}

}  // namespace lumen::interp
