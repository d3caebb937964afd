// Small scenes shared by the radiosity tests: unit squares in the catalogue configurations,
// regular polygons standing in for discs, and closed boxes meshed from the inside.
#pragma once
#include <cmath>
#include <numbers>
#include <vector>

#include <glm/vec3.hpp>

#include "render/radiosity/mesher.hpp"
#include "render/radiosity/patch.hpp"

namespace lumen::render::radiosity::testing {

// a x b rectangle in z = 0 facing +z, corner at the origin.
inline Patch floor_rect(double a, double b) {
    return make_patch({{0, 0, 0}, {a, 0, 0}, {a, b, 0}, {0, b, 0}});
}
// a x b rectangle in z = c facing -z, directly above floor_rect(a, b).
inline Patch ceiling_rect(double a, double b, double c) {
    return make_patch({{0, 0, c}, {0, b, c}, {a, b, c}, {a, 0, c}});
}
// l (along x) x h (along z) wall in y = 0 facing +y, sharing the x edge with floor_rect(l, w).
inline Patch wall_rect(double l, double h) {
    return make_patch({{0, 0, 0}, {0, 0, h}, {l, 0, h}, {l, 0, 0}});
}
// Regular n-gon approximating a disc of radius r centred at (0, 0, z), facing up or down.
inline Patch disc_polygon(double r, double z, bool up, int n) {
    std::vector<glm::dvec3> v;
    for (int k = 0; k < n; ++k) {
        const double phi = 2 * std::numbers::pi * (up ? k : -k) / n;
        v.push_back({r * std::cos(phi), r * std::sin(phi), z});
    }
    return make_patch(std::move(v));
}
// The inside of the unit cube [0,1]^3, each face an m x m grid, normals inward.
inline std::vector<Patch> unit_cube_inside(int m, glm::dvec3 rho = glm::dvec3(0.5)) {
    scene::Object box;
    box.shape = scene::Box{{0, 0, 0}, {1, 1, 1}};
    MeshOptions opt;
    opt.max_edge = 1.0 / m;
    opt.inward = true;
    return mesh_object(box, opt, {rho, glm::dvec3(0), 0});
}

}  // namespace lumen::render::radiosity::testing
