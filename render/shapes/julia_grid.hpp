// Where a julia_fractal (quaternion, or hypercomplex sqr and cube) can be inside, on a grid
// over its bounding cube, proved by interval arithmetic: a cell is empty when every point of
// it escapes, the iterates' interval enclosures passing the exit value before max_iteration. POV-Ray marches every ray through
// the bounding sphere; a ray whose span crosses only empty cells meets no inside point at any
// step, so its march can be skipped with the same result (no hit).
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

namespace lumen::render {

struct JuliaFractalShape;

class JuliaGrid {
public:
    // Null where no grid is built (the other hypercomplex functions, no iterations).
    static std::shared_ptr<const JuliaGrid> build(const JuliaFractalShape& s);

    // False only when no point of the segment a-b can be inside; else `last` is where along
    // it (0 at a, 1 at b) no further point can be.
    bool maybe_span(const glm::dvec3& a, const glm::dvec3& b, double& last) const;
    bool segment_may_hit(const glm::dvec3& a, const glm::dvec3& b) const {
        double last;
        return maybe_span(a, b, last);
    }
    bool may_contain(const glm::dvec3& p) const;
    // The share of cells that may hold inside points (for tests and tuning).
    double occupied_fraction() const;

private:
    int n_ = 0;
    double lo_ = 0, cell_ = 1;
    int box_lo_[3] = {0, 0, 0}, box_hi_[3] = {0, 0, 0};  // the maybe-cells' range (hi past)
    std::vector<uint8_t> maybe_;
    double first_maybe(const glm::dvec3& a, const glm::dvec3& b) const;
    bool at(int x, int y, int z) const { return maybe_[size_t((z * n_ + y) * n_ + x)] != 0; }
};

}  // namespace lumen::render
