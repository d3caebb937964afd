// ShapeData, the renderer's prepared primitive, and its dispatch, derived from the shape list
// (scene/shape_list.hpp): one alternative per listed shape, in list order.
#pragma once
#include <variant>

#include "render/shapes.hpp"

namespace lumen::render {

#define LUMEN_ASSERT_REGISTERED(T, ...)                                                    \
    static_assert(RegisteredShape<scene::T>,                                               \
                  "scene::" #T " needs ShapeTraits and intersect/inside/bounds/solid_bounds " \
                  "in render/shapes/ (see render/shapes/shape.hpp)");
LUMEN_PRIMITIVE_SHAPES(LUMEN_ASSERT_REGISTERED)
#undef LUMEN_ASSERT_REGISTERED

template <class... T> using PreparedVariant = std::variant<typename ShapeTraits<T>::Prepared...>;
using ShapeData = scene::PrimitiveShapes::apply<PreparedVariant>;

inline bool shape_intersect(const ShapeData& d, const LocalRay& r, double tmin, double tmax,
                            ShapeHit& h) {
    return std::visit([&](const auto& s) { return intersect(s, r, tmin, tmax, h); }, d);
}
inline bool shape_inside(const ShapeData& d, const glm::dvec3& p) {
    return std::visit([&](const auto& s) { return inside(s, p); }, d);
}
inline Aabb shape_bounds(const ShapeData& d) {
    return std::visit([](const auto& s) { return bounds(s); }, d);
}
inline Aabb shape_solid_bounds(const ShapeData& d) {
    return std::visit([](const auto& s) { return solid_bounds(s); }, d);
}
inline Aabb shape_bounds_within(const ShapeData& d, const Aabb& clip) {
    return std::visit([&](const auto& s) { return bounds_within(s, clip); }, d);
}

// The prepared shape of a primitive; false for CSG and unsupported shapes.
bool prepare_shape(const scene::Shape& shape, bool accelerate, ShapeData& out);
// POV-Ray's minimum hit distance for a primitive (kDepthDefault for the rest).
double min_depth_of(const scene::Shape& shape);
// Replaces a primitive by the same shape in world space when its kind allows that under xf
// (each shape's ShapeTraits::bake); false leaves the transform to be applied per ray.
bool bake_transform(const scene::Shape& shape, const scene::Transform& xf, ShapeData& out);

}  // namespace lumen::render
