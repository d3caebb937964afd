// julia_fractal: the 3-D slice of a 4-D Julia set, found as POV-Ray finds it: the ray clipped
// to the bounding sphere, marched in steps of the distance estimate (at least 1/precision)
// until the inside/outside state changes, the last step bisected down to 1e-7, and the normal
// taken from the derivative of the iteration chain.
#pragma once
#include <memory>

#include <glm/vec4.hpp>

#include "render/shapes/julia_grid.hpp"

#include "render/shapes/shape.hpp"

namespace lumen::render {

struct JuliaFractalShape {
    scene::JuliaAlgebra algebra = scene::JuliaAlgebra::Quaternion;
    scene::JuliaFunction function = scene::JuliaFunction::Sqr;
    glm::dvec4 c{1, 0, 0, 0};
    glm::dvec2 exponent{0};    // pwr's complex exponent
    int iterations = 20;
    double step = 0.05;        // 1 / precision
    glm::dvec4 slice{0, 0, 0, 1};
    double slice_distance = 0;
    double radius2 = 4, exit_value = 4;
    double log_exit = 1.3862943611198906;  // ln exit_value, rounded up
    bool csg_child = false;  // lists every crossing, not only the first
    std::shared_ptr<const JuliaGrid> grid;  // where it can be inside; null: anywhere
};

JuliaFractalShape make_julia_fractal(const scene::JuliaFractal& j);
bool intersect(const JuliaFractalShape& s, const LocalRay& r, double tmin, double tmax,
               ShapeHit& h);
bool inside(const JuliaFractalShape& s, const glm::dvec3& p);
Aabb bounds(const JuliaFractalShape& s);
inline Aabb solid_bounds(const JuliaFractalShape& s) { return bounds(s); }

// POV-Ray's Fractal_Tolerance: the start offset and the bisection's end (object space).
inline constexpr double kJuliaTolerance = 1e-7;
inline constexpr double kDepthJulia = kJuliaTolerance;

template <>
struct ShapeTraits<scene::JuliaFractal>
    : PreparedBy<scene::JuliaFractal, JuliaFractalShape, make_julia_fractal, &kDepthJulia> {
    // Not baked: the step and tolerances are in the fractal's own space.
    static bool bake(const scene::JuliaFractal&, const scene::Transform&, JuliaFractalShape&) {
        return false;
    }
};

}  // namespace lumen::render
