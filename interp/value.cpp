#include "interp/value.hpp"

namespace lumen::interp {

namespace {

// Names in the order of Value::Variant's alternatives.
constexpr const char* kTypeNames[] = {
    "empty value", "float",       "vector",      "colour",       "string",     "array",
    "block",       "object",      "texture",     "pigment",      "finish",     "normal",
    "interior",    "material",    "camera",      "light_source", "transform",  "color_map",
    "pigment_map", "texture_map", "normal_map",  "fog",          "rainbow",    "media",      "sky_sphere",
    "macro",
    "function",    "file",        "unsupported feature",
};
static_assert(std::size(kTypeNames) == std::variant_size_v<Value::Variant>);

}  // namespace

const char* Value::type_name() const { return kTypeNames[v.index()]; }

}  // namespace lumen::interp
