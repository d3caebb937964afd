// Dispatch from scene shapes to their ShapeTraits. Each visitor names CSG and unsupported
// shapes explicitly and takes only registered primitives otherwise, so a listed shape without
// its render side is a compile error here too.
#include "render/shapes/shape_data.hpp"

#include <cmath>

#include <glm/matrix.hpp>

#include "render/shapes/linear_maps.hpp"

namespace lumen::render {

namespace {

// What a visitor over scene::Shape answers for what is not a primitive.
template <class Result> struct NotPrimitive {
    Result operator()(const scene::Csg&) const { return Result{}; }
    Result operator()(const scene::UnsupportedShape&) const { return Result{}; }
};

template <class... F> struct Overloaded : F... { using F::operator()...; };
template <class... F> Overloaded(F...) -> Overloaded<F...>;

}  // namespace

bool prepare_shape(const scene::Shape& shape, bool accelerate, ShapeData& out) {
    return std::visit(Overloaded{NotPrimitive<bool>{},
                                 [&]<RegisteredShape T>(const T& s) {
                                     out = ShapeTraits<T>::prepare(s, accelerate);
                                     return true;
                                 }},
                      shape);
}

double min_depth_of(const scene::Shape& shape) {
    return std::visit(Overloaded{[](const scene::Csg&) { return kDepthDefault; },
                                 [](const scene::UnsupportedShape&) { return kDepthDefault; },
                                 []<RegisteredShape T>(const T&) {
                                     return double(ShapeTraits<T>::min_depth);
                                 }},
                      shape);
}

bool bake_transform(const scene::Shape& shape, const scene::Transform& xf, ShapeData& out) {
    double det = glm::determinant(linear_part(xf));
    if (!(det != 0) || !std::isfinite(det)) return false;
    return std::visit(Overloaded{NotPrimitive<bool>{},
                                 [&]<RegisteredShape T>(const T& s) {
                                     typename ShapeTraits<T>::Prepared baked;
                                     if (!ShapeTraits<T>::bake(s, xf, baked)) return false;
                                     out = std::move(baked);
                                     return true;
                                 }},
                      shape);
}

}  // namespace lumen::render
