// Objects of the scene graph: primitives and CSG with their modifiers, as plain data.
// Geometry is stored in the object's own coordinates as written; `transform` maps it to world.
#pragma once
#include <array>
#include <memory>
#include <optional>
#include <variant>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "scene/texture.hpp"
#include "scene/transform.hpp"
#include "scene/unsupported.hpp"

namespace lumen::scene {

struct Object;
using ObjectPtr = std::shared_ptr<const Object>;
struct Light;

struct Sphere { glm::dvec3 center{0}; double radius = 1; };
struct Plane { glm::dvec3 normal{0, 1, 0}; double distance = 0; };  // n̂·p = d, n normalised
struct Box { glm::dvec3 min{-1}, max{1}; };                         // reordered per axis
struct Cylinder { glm::dvec3 base{0}, cap{0, 1, 0}; double radius = 1; bool open = false; };
struct Cone {
    glm::dvec3 base{0}; double base_radius = 1;
    glm::dvec3 cap{0, 1, 0}; double cap_radius = 0;
    bool open = false;
};
struct Torus { double major = 1, minor = 0.25; bool sturm = false; };  // XZ plane, around Y
struct Disc { glm::dvec3 center{0}, normal{0, 1, 0}; double radius = 1, hole = 0; };
struct Triangle {
    std::array<glm::dvec3, 3> p{};
    std::array<glm::dvec3, 3> n{};  // vertex normals (normalised), used when smooth
    bool smooth = false;
};
struct Polygon { std::vector<glm::dvec3> points; };  // as written (sub-polygons closed)
struct Mesh {
    std::vector<glm::dvec3> vertices;
    std::vector<glm::dvec3> normals;
    std::vector<glm::dvec2> uvs;
    struct Face {
        std::array<int, 3> v{};       // vertex indices
        std::array<int, 3> n{-1, -1, -1};  // normal indices (-1 = flat)
        std::array<int, 3> tex{-1, -1, -1};  // texture_list indices (-1 = object texture)
    };
    std::vector<Face> faces;
    std::vector<LayeredTexture> textures;  // texture_list / per-triangle textures
    std::optional<glm::dvec3> inside_vector;
};
enum class CsgOp { Union, Merge, Intersection, Difference };
struct Csg {
    CsgOp op = CsgOp::Union;
    std::vector<ObjectPtr> children;
    // Light sources written inside the CSG, in its coordinates: lights of the scene that move
    // with it (the interpreter adds them to Scene::lights), never geometry.
    std::vector<std::shared_ptr<const Light>> lights{};
};
// A shape lumen does not render (blob, isosurface, text, ...); rendering it is an error.
struct UnsupportedShape { Unsupported what; };

using Shape = std::variant<Sphere, Plane, Box, Cylinder, Cone, Torus, Disc, Triangle, Polygon,
                           Mesh, Csg, UnsupportedShape>;

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
    std::vector<Unsupported> unsupported;  // unsupported modifiers used on this object
    SourceLoc loc;
};

}  // namespace lumen::scene
