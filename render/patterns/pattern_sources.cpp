#include "render/patterns/pattern_sources.hpp"

#include "render/pigment.hpp"

namespace lumen::render {
namespace {

// The voxel cell holding p along one axis, the next voxel (wrapping) and the fraction between.
struct Cell {
    int i, next;
    double t;
};
Cell cell(double v, int n) {
    const double s = v * n;
    const int i = int(s);
    return {i, (i + 1) % n, s - i};
}

double lerp(double a, double b, double t) { return a + t * (b - a); }

}  // namespace

double evaluate(const scene::pattern::Average&, const glm::dvec3&) { return 0.0; }

// POV-Ray's grey of the colour (0.297 r + 0.589 g + 0.114 b), the pigment evaluated at the
// pattern point.
double evaluate(const scene::pattern::PigmentPattern& k, const glm::dvec3& p) {
    const scene::Colour c = evaluate_pigment(k.pigment.get(), p);
    return 0.297 * c.r + 0.589 * c.g + 0.114 * c.b;
}

// The unit cube holds the grid; outside it the density is 0. Interpolation 1 blends the
// eight voxels around p with voxel i at i/n (not its centre), wrapping at the far faces.
double evaluate(const scene::pattern::DensityFile& k, const glm::dvec3& p) {
    const scene::pattern::DensityGrid& g = *k.grid;
    if (p.x < 0 || p.x >= 1 || p.y < 0 || p.y >= 1 || p.z < 0 || p.z >= 1) return 0;
    const Cell x = cell(p.x, g.nx), y = cell(p.y, g.ny), z = cell(p.z, g.nz);
    if (k.interpolate % 10 != 1) return g.at(x.i, y.i, z.i);
    auto plane = [&](int zi) {
        return lerp(lerp(g.at(x.i, y.i, zi), g.at(x.next, y.i, zi), x.t),
                    lerp(g.at(x.i, y.next, zi), g.at(x.next, y.next, zi), x.t), y.t);
    };
    return lerp(plane(z.i), plane(z.next), z.t);
}

}  // namespace lumen::render
