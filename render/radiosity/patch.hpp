// Radiosity patches: planar convex polygons carrying a constant radiosity. Patches are the
// unknowns of the classical (finite-element, diffuse) radiosity system; elements are patches
// produced by subdividing a larger one, so they share the same type.
#pragma once
#include <cstdint>
#include <random>
#include <vector>

#include <glm/vec3.hpp>

namespace lumen::render::radiosity {

struct Patch {
    std::vector<glm::dvec3> vertices;  // convex, planar, counter-clockwise seen from the front
    glm::dvec3 normal{0, 0, 1};        // unit front normal (right-hand rule on the vertices)
    glm::dvec3 centroid{0};
    double area = 0;
    glm::dvec3 rho{0};       // diffuse reflectance per channel, in [0, 1)
    glm::dvec3 emission{0};  // emitted radiosity E per channel
    int object = -1;         // index of the scene object it came from (-1: none)
    int texture = -1;        // a mesh face's entry in its texture_list (-1: the object's texture)

    bool degenerate() const { return !(area > 0); }
};

// Builds a patch from its vertices; area, normal and centroid come from Newell's method, so
// slightly non-planar quads still get a sensible normal. Zero-area input gives area 0 and
// normal (0,0,1) rather than NaN.
Patch make_patch(std::vector<glm::dvec3> vertices, glm::dvec3 rho = glm::dvec3(0),
                 glm::dvec3 emission = glm::dvec3(0), int object = -1);

// A piece of `whole` with these vertices: material, object and texture are inherited.
Patch part_of(const Patch& whole, std::vector<glm::dvec3> vertices);

// The same patch facing the other way (vertex order reversed).
Patch flipped(const Patch& p);

// A uniformly distributed point on the patch from two uniform numbers in [0, 1).
glm::dvec3 sample_point(const Patch& p, double u1, double u2);

// Splits a patch into elements whose edges are at most `max_edge` long (approximately: quads
// become an m x n bilinear grid, triangles k^2 similar triangles, other polygons a triangle
// fan first). Material and object index are inherited. max_edge <= 0 returns the patch.
std::vector<Patch> subdivide(const Patch& p, double max_edge);

// Ray / patch intersection: the distance t > t_min along `dir` (not necessarily unit) at
// which the ray crosses the patch, edges included, or a negative number when it misses.
double intersect(const Patch& p, const glm::dvec3& origin, const glm::dvec3& dir,
                 double t_min = 1e-9);

// Total area of a patch set.
double total_area(const std::vector<Patch>& patches);

}  // namespace lumen::render::radiosity
