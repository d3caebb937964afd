// Objects of the scene graph: primitives and CSG with their modifiers, as plain data.
// Geometry is stored in the object's own coordinates as written; `transform` maps it to world.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <variant>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "scene/shape_list.hpp"
#include "scene/photons.hpp"
#include "scene/shapes.hpp"
#include "scene/texture.hpp"
#include "scene/transform.hpp"
#include "scene/unsupported.hpp"

namespace lumen::scene {

struct Object;
using ObjectPtr = std::shared_ptr<const Object>;
struct Light;

enum class CsgOp { Union, Merge, Intersection, Difference };
struct Csg {
    CsgOp op = CsgOp::Union;
    std::vector<ObjectPtr> children;
    // Light sources written inside the CSG, in its coordinates: lights of the scene that move
    // with it (the interpreter adds them to Scene::lights), never geometry.
    std::vector<std::shared_ptr<const Light>> lights{};
    // light_group { }: a union whose lights light only its members (and whose members get
    // the scene's other lights only with `global_lights on`). `light_group` numbers the group
    // once it is placed in the scene (interp: place_csg_lights); 0 elsewhere.
    bool is_light_group = false, global_lights = false;
    uint32_t light_group = 0;
};
// A shape lumen does not render (blob, isosurface, text, ...); rendering it is an error.
struct UnsupportedShape { Unsupported what; };

// The listed primitives (scene/shape_list.hpp), then what is not a primitive.
using PrimitiveShapes =
    shape_list_detail::Tail<TypeList<void LUMEN_PRIMITIVE_SHAPES(LUMEN_COMMA_SHAPE_TYPE)>>::type;
using Shape = std::variant<LUMEN_PRIMITIVE_SHAPES(LUMEN_SHAPE_TYPE_COMMA) Csg, UnsupportedShape>;

struct Object {
    Shape shape;
    Transform transform;              // object -> world
    LayeredTexture texture;           // empty = inherit from the parent CSG, else the default
    LayeredTexture interior_texture;  // empty = same as texture
    std::optional<Interior> interior; // empty = default interior
    std::vector<ObjectPtr> clipped_by;  // in world space (already transformed)
    std::vector<ObjectPtr> bounded_by;  // in world space (already transformed)
    bool inverse = false, hollow = false, no_shadow = false, no_image = false,
         no_reflection = false, double_illuminate = false, no_radiosity = false;
    // Object-level `uv_mapping`: every texture given after it is uv-mapped (Pattern::uv_mapping).
    bool uv_mapping = false;
    std::optional<ObjectPhotons> photons;  // its photons { } block (CSG children inherit it)
    // A union that is a photon target is shot member by member unless `split_union off`.
    bool split_union = true;
    std::vector<Unsupported> unsupported;  // unsupported modifiers used on this object
    SourceLoc loc;
};

}  // namespace lumen::scene
