// Runtime values of the SDL interpreter, and the evaluated items of a block body.
//
// Evaluation model: a block body (`sphere { ... }`) is first *flattened*: directives run,
// macro calls are expanded in place, expressions are evaluated and nested blocks are built,
// giving a vector<Item>. A builder (interp/build_*.cpp) then reads those items with an
// ItemCursor and produces a typed scene value (Object, Pigment, ...).
#pragma once
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "function/program.hpp"
#include "function/spline.hpp"
#include "parser/ast.hpp"
#include "scene/scene.hpp"

namespace lumen::interp {

struct Value;
struct BlockValue;
struct ArrayValue;
struct MacroValue;
struct FunctionValue;
struct FileValue;

// A vector of 2..5 components, or a 12-component matrix literal.
struct VecN {
    std::vector<double> c;
    glm::dvec3 xyz() const {  // missing components are 0
        return {c.size() > 0 ? c[0] : 0, c.size() > 1 ? c[1] : 0, c.size() > 2 ? c[2] : 0};
    }
};

// Layered texture values and material.
struct TextureValue { scene::LayeredTexture layers; };
struct MaterialValue {
    scene::LayeredTexture texture, interior_texture;
    std::optional<scene::Interior> interior;
    scene::Transform transform;
};
struct ColourMapValue { scene::ColourMap entries; };
struct PigmentMapValue { scene::PigmentMap entries; };
struct TextureMapValue { scene::TextureMap entries; };
struct NormalMapValue { scene::NormalMap entries; };

struct Value {
    using Variant = std::variant<
        std::monostate,                                   // no value (e.g. empty macro result)
        double,                                           // float
        VecN,                                             // vector
        scene::Colour,                                    // colour
        std::string,                                      // string
        std::shared_ptr<ArrayValue>,                      // array (reference semantics)
        std::shared_ptr<const BlockValue>,                // generic block (data blocks)
        scene::ObjectPtr,                                 // object
        std::shared_ptr<const TextureValue>,              // texture (layers)
        scene::PigmentPtr,                                // pigment
        scene::FinishPtr,                                 // finish
        scene::NormalPtr,                                 // normal
        std::shared_ptr<const scene::Interior>,           // interior
        std::shared_ptr<const MaterialValue>,             // material
        std::shared_ptr<const scene::Camera>,             // camera
        std::shared_ptr<const scene::Light>,              // light_source
        std::shared_ptr<const scene::Transform>,          // transform
        std::shared_ptr<const ColourMapValue>,            // color_map
        std::shared_ptr<const PigmentMapValue>,           // pigment_map
        std::shared_ptr<const TextureMapValue>,           // texture_map
        std::shared_ptr<const NormalMapValue>,            // normal_map
        std::shared_ptr<const scene::Fog>,                // fog
        std::shared_ptr<const scene::Rainbow>,            // rainbow
        std::shared_ptr<const scene::Media>,              // media
        std::shared_ptr<const scene::SkySphere>,          // sky_sphere
        std::shared_ptr<const MacroValue>,                // macro
        std::shared_ptr<const FunctionValue>,             // function / spline (not evaluated)
        std::shared_ptr<FileValue>,                       // #fopen file (interp/file_io.hpp)
        scene::Unsupported>;                              // unsupported feature
    Value() = default;
    Value(Variant value, SourceLoc where = {}, std::shared_ptr<const BlockValue> edit = nullptr)
        : v(std::move(value)), loc(where), edits(std::move(edit)) {}

    Variant v;
    SourceLoc loc;  // where the value was written
    // pigment/normal blocks that do not start from an identifier: the flattened block, so
    // that a parent that already has a pigment/normal can apply it as an edit (POV modifies
    // the texture's pigment: `texture { T pigment { scale 2 } }` scales T's pigment).
    std::shared_ptr<const BlockValue> edits;

    template <class T> bool is() const { return std::holds_alternative<T>(v); }
    template <class T> const T& as() const { return std::get<T>(v); }
    const char* type_name() const;  // "float", "vector", "colour", "object", ...
};

// One evaluated item of a block body.
struct Item {
    enum class Kind { Keyword, Value, Comma, MapEntry, Literals } kind = Kind::Value;
    std::string keyword;                 // Keyword
    Value value;                         // Value (nested blocks arrive as built values)
    std::vector<Item> entry;             // MapEntry: the flattened items inside [ ]
    SourceLoc loc;
    // Literals: a run of floats, vectors and commas, one item each when read
    // (literal_items.hpp); the run belongs to the syntax tree, which outlives evaluation.
    const ast::LiteralRun* literals = nullptr;
};

// A block the core evaluator does not build itself: its keyword and flattened items.
struct BlockValue {
    std::string keyword;
    std::vector<Item> items;
    SourceLoc loc;
};

struct ArrayValue {
    std::vector<size_t> dims;
    std::vector<std::optional<Value>> elems;  // row-major; nullopt = not initialised
};

struct MacroValue {
    const ast::Node* node = nullptr;  // the Macro node (owned by the parse cache)
};

struct FunctionValue {
    const ast::Node* node = nullptr;  // the `function`/`spline` Block node
    std::string keyword;
    fn::ProgramPtr program;  // compiled where declared; null for the forms lumen cannot run
    std::string why_not;     // then: the feature, for the error where it is used
    std::shared_ptr<const fn::Spline> spline;  // a `spline { }` (called as S(t) in SDL)
};

}  // namespace lumen::interp
