// Internal declarations shared by the scene builders (interp/build_*.cpp). Each builder reads
// a block body through an ItemCursor, so map entries (`[0.5 pigment_body]`) and #declared
// copies reuse the same code as the blocks themselves.
#pragma once
#include <cmath>
#include <string>
#include <vector>

#include "interp/builders.hpp"
#include "interp/item_cursor.hpp"

namespace lumen::interp {

// ---- transforms (build_transform.cpp) -------------------------------------------------------
scene::Transform translation(const glm::dvec3& v);
scene::Transform rotation(const glm::dvec3& degrees);  // x, then y, then z (left-handed)
scene::Transform scaling(const glm::dvec3& s);
scene::Transform inverted(const scene::Transform& t);
// If `kw` (already consumed) is translate/rotate/scale/matrix/transform, reads its argument
// and returns true with the transform in `out`. A Transform value item counts too.
bool read_transform(ItemCursor& cur, const Item& kw, scene::Transform& out);
const std::vector<std::string>& transform_keywords();
scene::Transform build_transform_block(ItemCursor& cur);

// Patterns move with everything written after them: a transform appends to the pattern's
// steps. Map entries are not transformed: a pigment's and a texture's entries are evaluated at
// their parent's pattern point (as POV-Ray does), and a normal's normal_map entries live in its
// pattern space. A uv_mapping pigment, normal or texture is left as it is (POV-Ray: transforms
// written outside it never move it); its own transforms act in uv space.
scene::PigmentPtr transformed(const scene::PigmentPtr& p, const scene::Transform& t);
scene::NormalPtr transformed(const scene::NormalPtr& n, const scene::Transform& t);
scene::TexturePtr transformed(const scene::TexturePtr& tex, const scene::Transform& t);
scene::LayeredTexture transformed(const scene::LayeredTexture& layers, const scene::Transform& t);
// A transform written inside the texture's own block: it moves the texture even under
// uv_mapping (in uv space), and its pigment and normal unless they are uv-mapped themselves.
void transform_own(scene::Texture& tex, const scene::Transform& t);

// A 2-vector `<a, b>` (a float stands for both): julia's constant, the uv_vectors of meshes
// and patches (build_mesh.cpp).
glm::dvec2 read_vector2(ItemCursor& cur, const std::string& after);

// ---- patterns (build_pattern.cpp) -----------------------------------------------------------
// If `kw` (already consumed) is a pattern type or pattern modifier, reads its arguments into
// `pattern` and returns true. `owner` is "pigment", "normal" or "texture": kinds in normals
// render as normals (scene/normal_forms.hpp) and are reported as "normal 'bumps'", the others
// as "pattern 'bozo'".
bool read_pattern_keyword(ItemCursor& cur, const Item& kw, scene::Pattern& pattern,
                          const std::string& owner);
// image_map { }, image_pattern { }, bump_map { } or material_map { } (build_image_map.cpp):
// reads the image and its modifiers into `pattern`'s kind and returns true; a located error
// where the block does not belong to `owner`. material_map's textures go to `textures`.
bool read_image_block(ItemCursor& cur, const Item& kw, scene::Pattern& pattern,
                      const std::string& owner, std::vector<scene::LayeredTexture>* textures);
// How many list entries `checker A, B` style patterns take (0 = no list form).
int pattern_list_size(scene::PatternType type);
// True for the pattern words that may be followed by a list (`checker A, B`).
bool is_list_pattern_word(const Item& item);
bool is_pattern_word(const Item& item);  // checker, bozo, gradient, ...
// The list entries of an object pattern, `object { OBJ A, B }`: a cursor over the block after
// the object, for the owner's list reader; finish() rejects anything left over.
struct ObjectEntries {
    ObjectEntries(ItemCursor& cur, const BlockValue& block);
    void finish();
    ItemCursor entries;
};
const std::vector<std::string>& pattern_keywords();
// `uv_mapping` at the start of a pigment, normal or texture block (after its identifier, if
// any; POV-Ray refuses it anywhere later, which read_pattern_keyword reports).
void read_leading_uv_mapping(ItemCursor& cur, scene::Pattern& pattern);
void mark_unsupported(scene::Pattern& pattern, const std::string& feature, SourceLoc loc);
// The arguments after a pattern keyword (`gradient <v>`, `mandel 25`), read into its kind
// (build_pattern_kinds.cpp).
void read_pattern_arguments(ItemCursor& cur, const Item& kw, scene::Pattern& pattern);
// A modifier that belongs to some kinds (`mortar`, `metric`, ...): read into the pattern's
// kind, or an error when the kind does not take it. False when `kw` is no such modifier.
bool read_pattern_kind_modifier(ItemCursor& cur, const Item& kw, scene::Pattern& pattern);
const std::vector<std::string>& pattern_kind_keywords();
// POV-Ray's checks of a pattern's modifiers once all are read (pavement's numbers), an error
// at `at` (the end of the block) when they fail.
void verify_pattern(ItemCursor& cur, SourceLoc at, scene::Pattern& pattern);
// A value POV-Ray stores in single precision (frequency, phase, turbulence omega and lambda,
// ...), rounded as it does; values beyond float's range are kept.
inline double single_precision(double v) {
    return std::fabs(v) <= 3.4028234663852886e38 ? double(float(v)) : v;
}
// The body of `slope { [point_at] <v> [, lo, hi] [altitude <a> [, lo, hi]] }`.
void read_slope_block(ItemCursor& cur, scene::pattern::Slope& slope);
// `warp { ... }`: appends the warp to the pattern's steps (build_warp.cpp).
void read_warp(ItemCursor& cur, const BlockValue& block, scene::Pattern& pattern);

// ---- maps (build_maps.cpp) ------------------------------------------------------------------
scene::ColourMap build_colour_map(ItemCursor& cur);
scene::PigmentMap build_pigment_map(ItemCursor& cur);
scene::TextureMap build_texture_map(ItemCursor& cur);
scene::NormalMap build_normal_map(ItemCursor& cur);
scene::SlopeMap build_slope_map(ItemCursor& cur);  // a slope_map block's body

// ---- materials (build_pigment/texture/finish/normal/interior/material.cpp) -------------------
// `base`: the pigment/normal the block edits (see edit_pigment); null = the #default one.
scene::PigmentPtr build_pigment(ItemCursor& cur, const scene::Pigment* base = nullptr);
scene::PigmentPtr solid_pigment(const scene::Colour& c, SourceLoc loc);
scene::FinishPtr build_finish(ItemCursor& cur);
// `finish { ... }` written where a finish already is (a copied texture, an object's texture):
// the fields the block wrote replace those of `base`; a declared finish replaces it whole.
scene::FinishPtr apply_finish(const scene::FinishPtr& base, const scene::FinishPtr& f);
scene::NormalPtr build_normal(ItemCursor& cur, const scene::Normal* base = nullptr);
// A pigment/normal value `v` written where `current` already is (in a texture, on an object):
// a block that did not start from a declared one edits a copy of `current`, as POV does.
scene::PigmentPtr edit_pigment(BuildContext& ctx, const Value& v, const scene::PigmentPtr& current);
scene::NormalPtr edit_normal(BuildContext& ctx, const Value& v, const scene::NormalPtr& current);
scene::LayeredTexture build_texture(ItemCursor& cur);
scene::Interior build_interior(ItemCursor& cur);
MaterialValue build_material(ItemCursor& cur);
// A fresh plain texture from the #default settings.
std::shared_ptr<scene::Texture> default_texture(const BuildContext& ctx, SourceLoc loc);

// ---- objects (build_object.cpp, build_csg.cpp, build_modifiers.cpp) -------------------------
scene::ObjectPtr build_object(ItemCursor& cur);  // any shape keyword, CSG or `object`
scene::ObjectPtr build_csg(ItemCursor& cur);
// A copy of a declared object with modifiers: `object { Ident ... }`, `mesh { MeshIdent ... }`.
scene::ObjectPtr read_object_copy(ItemCursor& cur);
scene::ObjectPtr build_mesh(ItemCursor& cur);   // build_mesh.cpp
scene::ObjectPtr build_mesh2(ItemCursor& cur);
scene::ObjectPtr build_text(ItemCursor& cur);   // build_text.cpp
scene::ObjectPtr build_prism(ItemCursor& cur);  // build_swept.cpp
scene::ObjectPtr build_bicubic_patch(ItemCursor& cur);  // build_bicubic_patch.cpp, as a mesh
scene::ObjectPtr build_lathe(ItemCursor& cur);
scene::ObjectPtr build_sor(ItemCursor& cur);
scene::ObjectPtr build_blob(ItemCursor& cur);  // build_blob.cpp
scene::ObjectPtr build_height_field(ItemCursor& cur);  // build_height_field.cpp
scene::ObjectPtr build_julia_fractal(ItemCursor& cur);  // build_julia_fractal.cpp
scene::ObjectPtr build_sphere_sweep(ItemCursor& cur);  // build_sphere_sweep.cpp
// build_isosurface.cpp: the isosurface, and what parametric shares with it: contained_by,
// and accuracy and max_gradient above 0 (else POV-Ray's warning and the default).
scene::ObjectPtr build_isosurface(ItemCursor& cur);
void read_container(ItemCursor& cur, const BlockValue& block, scene::Container& c);
double positive_or_default(ItemCursor& cur, const Item& kw, double fallback, const char* shape);
scene::ObjectPtr build_parametric(ItemCursor& cur);  // build_parametric.cpp
// The object of an isosurface or parametric `shape` (named `name` in the warning): its
// modifiers read (`extra` takes the shape's own keywords into `shape`), an empty container
// warned about.
template <class Shape, class Extra>
scene::ObjectPtr contained_object(ItemCursor& cur, Shape& shape, const Extra& extra,
                                  const std::vector<std::string>& words, const char* name) {
    scene::Object obj;
    obj.loc = cur.block_loc();
    read_object_modifiers(cur, obj, extra, words);
    if (shape.container.empty())
        cur.warn(cur.block_loc(), std::string("the ") + name + "'s container is empty: nothing is drawn");
    obj.shape = std::move(shape);
    return std::make_shared<scene::Object>(std::move(obj));
}
// build_spline.cpp: a spline block's entries, and the type a keyword names.
std::shared_ptr<const fn::Spline> build_spline(ItemCursor& cur);
std::optional<fn::SplineType> spline_type(std::string_view word);
scene::ObjectPtr unsupported_object(const scene::Unsupported& u);
bool is_unsupported_shape(const std::string& keyword);
// Reads the object modifiers that follow a shape's own arguments. `extra` handles
// shape-specific keywords (open, sturm, ...) and returns false for unknown ones.
template <class Extra>
void read_object_modifiers(ItemCursor& cur, scene::Object& obj, const Extra& extra,
                           const std::vector<std::string>& extra_keywords);
bool apply_object_modifier(ItemCursor& cur, const Item& item, scene::Object& obj);
[[noreturn]] void fail_object_item(ItemCursor& cur, const Item& item,
                                   const std::vector<std::string>& extra_keywords);
void transform_object(scene::Object& obj, const scene::Transform& t);
scene::ObjectPtr transformed(const scene::ObjectPtr& obj, const scene::Transform& t);

template <class Extra>
void read_object_modifiers(ItemCursor& cur, scene::Object& obj, const Extra& extra,
                           const std::vector<std::string>& extra_keywords) {
    while (!cur.at_end()) {
        const Item& item = cur.next();
        if (extra(item)) continue;
        if (apply_object_modifier(cur, item, obj)) continue;
        fail_object_item(cur, item, extra_keywords);
    }
}

// ---- scene-level blocks ---------------------------------------------------------------------
scene::Camera build_camera(ItemCursor& cur);
scene::Light build_light(ItemCursor& cur);
// Moves a light (position, point_at, area axes, looks_like, projected_through) by `t`.
void transform_light(scene::Light& light, const scene::Transform& t);
// The light sources inside CSG `obj` and its descendants, moved to world space (`to_world` is
// the transform of what encloses obj), appended to the scene's lights; the light_groups
// inside are numbered (Csg::light_group, and Light::group of the lights written directly in
// them). Returns obj, or a copy of the path down to each group where it holds any
// (build_csg.cpp).
scene::ObjectPtr place_csg_lights(const scene::ObjectPtr& obj, const scene::Transform& to_world,
                                  scene::Scene& scene);
scene::Fog build_fog(ItemCursor& cur);
scene::Rainbow build_rainbow(ItemCursor& cur);
// media { } and density { } (build_media.cpp). A density is a pigment whose colour scales the
// media's coefficients.
scene::MediaPtr build_media(ItemCursor& cur);
scene::PigmentPtr build_density(ItemCursor& cur);
// density_map { [v colour | density] ... }: a colour_map, or a pigment_map where an entry is a
// density (build_maps.cpp).
Value build_density_map(ItemCursor& cur, SourceLoc loc);
// The media with its densities moved by t (an object's or interior's transform).
scene::MediaPtr transformed(const scene::MediaPtr& media, const scene::Transform& t);
scene::SkySphere build_sky_sphere(ItemCursor& cur);
scene::Colour build_background(ItemCursor& cur);
void apply_global_settings(ItemCursor& cur, scene::GlobalSettings& globals);

// The BlockValue inside a value item (data blocks such as `reflection { }`), or null.
const BlockValue* block_of(const Item& item, std::string_view keyword = {});

// ---- photons (build_photons.cpp) ------------------------------------------------------------
// global_settings' photons { } body; features lumen does not render go to `unsupported`.
scene::PhotonSettings build_global_photons(ItemCursor& cur,
                                           std::vector<scene::Unsupported>& unsupported);
void read_object_photons(ItemCursor& cur, const BlockValue& block, scene::Object& obj);
void read_light_photons(ItemCursor& cur, const BlockValue& block, scene::Light& light);

}  // namespace lumen::interp
