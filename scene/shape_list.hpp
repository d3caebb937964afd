// The one list of the primitive shapes lumen renders. Everything that enumerates shapes is
// derived from it: scene::Shape, the renderer's ShapeData and its dispatch (each entry needs
// a ShapeTraits specialisation, render/shapes/shape.hpp), the interpreter's readers and block
// keywords, --dump-scene and the radiosity mesher (std::visit without a catch-all). Adding an
// entry without one of those pieces does not compile.
//
// X(Type, keyword...): scene::Type is the plain-data struct (scene/shapes.hpp), the keywords
// are the SDL blocks that build it, in the order "did you mean" suggestions try them.
#pragma once
#include <cstddef>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#define LUMEN_PRIMITIVE_SHAPES(X)              \
    X(Sphere, "sphere")                        \
    X(Plane, "plane")                          \
    X(Box, "box")                              \
    X(Cylinder, "cylinder")                    \
    X(Cone, "cone")                            \
    X(Torus, "torus")                          \
    X(Disc, "disc")                            \
    X(Triangle, "triangle", "smooth_triangle") \
    X(Polygon, "polygon")                      \
    X(Mesh, "mesh", "mesh2", "bicubic_patch")  \
    X(Text, "text")                            \
    X(Prism, "prism")                          \
    X(Lathe, "lathe")                          \
    X(Sor, "sor")                              \
    X(Poly, "poly", "cubic", "quartic", "polynomial") \
    X(Quadric, "quadric")                      \
    X(Superellipsoid, "superellipsoid")        \
    X(Blob, "blob")                            \
    X(Ovus, "ovus")                            \
    X(HeightField, "height_field")             \
    X(JuliaFractal, "julia_fractal")           \
    X(SphereSweep, "sphere_sweep")             \
    X(Isosurface, "isosurface")                \
    X(Parametric, "parametric")

namespace lumen::scene {

// A list of types, to derive variants and typed tests from.
template <class... T> struct TypeList {
    template <template <class...> class F> using apply = F<T...>;
    static constexpr size_t size = sizeof...(T);
};

namespace shape_list_detail {
template <class L> struct Tail;
template <class H, class... T> struct Tail<TypeList<H, T...>> { using type = TypeList<T...>; };
}  // namespace shape_list_detail

// A scene shape, `Type,` or `, Type`, for building type lists from the X-macro.
#define LUMEN_SHAPE_TYPE_COMMA(T, ...) T,
#define LUMEN_COMMA_SHAPE_TYPE(T, ...) , T
#define LUMEN_SHAPE_KEYWORDS_COMMA(T, ...) __VA_ARGS__,

// The keywords of every listed shape.
inline constexpr std::string_view kShapeKeywords[] = {
    LUMEN_PRIMITIVE_SHAPES(LUMEN_SHAPE_KEYWORDS_COMMA)};

// Object blocks POV-Ray has and lumen does not render yet: each becomes an UnsupportedShape.
inline constexpr std::string_view kUnsupportedShapeKeywords[] = {
    "lemon"};

// `first`, then `rest`: keyword tables that start with one of the lists above.
template <size_t N>
std::vector<std::string> keywords_then(const std::string_view (&first)[N],
                                       std::initializer_list<const char*> rest) {
    std::vector<std::string> words(std::begin(first), std::end(first));
    words.insert(words.end(), rest.begin(), rest.end());
    return words;
}

}  // namespace lumen::scene
