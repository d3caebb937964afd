// The primitive shapes of scene/shape_list.hpp as plain data, in the object's own
// coordinates as written.
#pragma once
#include <array>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "scene/texture.hpp"

namespace lumen::scene {

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
}  // namespace lumen::scene
