// What every primitive of scene/shape_list.hpp must provide to the renderer, one file pair
// per shape in render/shapes/. A shape is hit by an object-space ray (origin o, direction d,
// d NOT unit length: it is the world unit direction through the inverse transform), so the
// parameter t is the same as the world distance. Degenerate input gives a shape that is never
// hit.
#pragma once
#include <concepts>
#include <memory>
#include <type_traits>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "render/bounds.hpp"
#include "scene/object.hpp"

namespace lumen::render {

struct LocalRay {
    glm::dvec3 o, d;
    glm::dvec3 at(double t) const { return o + t * d; }
};

// What a shape reports; the normal is in object space, outward, not necessarily unit length.
struct ShapeHit {
    double t = 0;
    glm::dvec3 normal{0, 1, 0};
    glm::dvec2 uv{0};
    const scene::LayeredTexture* texture = nullptr;  // per-face mesh texture, if any
};

// Minimum depths of POV-Ray's objects: hits closer to the ray origin than this are ignored
// (POV-Ray's per-object DEPTH_TOLERANCE values).
inline constexpr double kDepthDefault = 1e-6;  // sphere, plane, box, disc, triangle, mesh, ...
inline constexpr double kDepthTorus = 1e-4;
inline constexpr double kDepthSwept = 1e-4;  // prism, lathe, sor
inline constexpr double kDepthPolygon = 1e-8;

// The render side of scene shape T. Only the specialisations exist, one in each shape's
// header, each with:
//   using Prepared = ...;                  the shape ready for intersection (a ShapeData type)
//   static constexpr double min_depth;     POV-Ray's minimum hit distance for the object
//   static Prepared prepare(const T&, bool accelerate);
//   static bool bake(const T&, const scene::Transform& xf, Prepared& out);
//       the same shape in world space, or false: xf stays a per-ray transform
template <class T> struct ShapeTraits;

// The common case: the prepared shape made by `make` from the scene shape alone. The depth
// is passed by address: clang before 18 takes no floating-point template arguments.
template <class T, class P, P (*make)(const T&), const double* depth = &kDepthDefault>
struct PreparedBy {
    using Prepared = P;
    static constexpr double min_depth = *depth;
    static P prepare(const T& shape, bool) { return make(shape); }
};

// Free functions every prepared shape has (found by argument-dependent lookup). A shape with
// no inside (disc, triangle, polygon) says so with inside() false and an empty solid box.
// Large prepared shapes (meshes, height fields) are held by pointer: these forward to them.
template <class P> struct IsHeldShape : std::false_type {};
template <class S> struct IsHeldShape<std::unique_ptr<S>> : std::true_type {};
template <class S> struct IsHeldShape<std::shared_ptr<S>> : std::true_type {};  // shared meshes
template <class P> concept HeldShape = IsHeldShape<P>::value;
template <HeldShape P>
bool intersect(const P& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h) {
    return intersect(*s, r, tmin, tmax, h);
}
template <HeldShape P> bool inside(const P& s, const glm::dvec3& p) { return inside(*s, p); }
template <HeldShape P> Aabb bounds(const P& s) { return bounds(*s); }
template <HeldShape P> Aabb solid_bounds(const P& s) { return solid_bounds(*s); }
// Where a shape's surface can be within `clip`: its box cut to it, unless the shape has a
// tighter answer of its own (quadrics: render/shapes/quadric.hpp).
template <class S> Aabb bounds_within(const S& s, const Aabb& clip) {
    return intersect(bounds(s), clip);
}

template <class S>
concept PreparedShape = requires(const S& s, const LocalRay& r, double t, ShapeHit& h,
                                 const glm::dvec3& p) {
    { intersect(s, r, t, t, h) } -> std::same_as<bool>;
    { inside(s, p) } -> std::same_as<bool>;
    { bounds(s) } -> std::same_as<Aabb>;        // where a hit can be
    { solid_bounds(s) } -> std::same_as<Aabb>;  // where a point can be inside
};

template <class T>
concept RegisteredShape =
    requires(const T& shape, bool accelerate, const scene::Transform& xf,
             typename ShapeTraits<T>::Prepared& out) {
        { ShapeTraits<T>::min_depth } -> std::convertible_to<double>;
        { ShapeTraits<T>::prepare(shape, accelerate) }
            -> std::same_as<typename ShapeTraits<T>::Prepared>;
        { ShapeTraits<T>::bake(shape, xf, out) } -> std::same_as<bool>;
    } && PreparedShape<typename ShapeTraits<T>::Prepared>;

}  // namespace lumen::render
