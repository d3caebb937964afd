// parametric: the surface (FX, FY, FZ)(u, v) over a uv rectangle, found as POV-Ray 3.7 finds
// it. The rectangle is split in halves, depth first, while the ray's slab through the bounds
// of every coordinate over the piece (from its corners and max_gradient, or from the
// `precompute` tables) stays within the container and nearer than the best depth; a piece
// narrower than the accuracy in uv or in depth gives the depth where the slabs begin. Normals
// are forward differences in u and v. It has no inside.
#pragma once
#include <array>
#include <memory>
#include <vector>

#include "function/vm.hpp"
#include "render/shapes/shape.hpp"

namespace lumen::render {

struct ParametricShape {
    scene::Parametric p;
    fn::Context context;
    bool valid = false;
    // `precompute`: per axis, the bounds (lo, hi) of the coordinate over each piece of the
    // first precompute_depth levels, by piece number (1 the whole, 2n and 2n + 1 the halves of
    // n); empty for an axis not precomputed.
    std::array<std::shared_ptr<const std::vector<glm::dvec2>>, 3> tables;
};

ParametricShape make_parametric(const scene::Parametric& s);
bool intersect(const ParametricShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
inline bool inside(const ParametricShape&, const glm::dvec3&) { return false; }
Aabb bounds(const ParametricShape& s);
inline Aabb solid_bounds(const ParametricShape&) { return {}; }

template <>
struct ShapeTraits<scene::Parametric>
    : PreparedBy<scene::Parametric, ParametricShape, make_parametric> {
    // Traced in its own space, where the functions are written.
    static bool bake(const scene::Parametric&, const scene::Transform&, ParametricShape&) {
        return false;
    }
};

}  // namespace lumen::render
