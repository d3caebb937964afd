#include "render/patterns/pattern_sources.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <unordered_map>

#include "function/vm.hpp"
#include "render/function_host.hpp"
#include "render/node.hpp"
#include "render/pigment.hpp"
#include "scene/object.hpp"

namespace lumen::render {
namespace {

// The voxel cell holding p along one axis, the next voxel (wrapping) and the fraction between.
struct Cell {
    int i, next;
    double t;
};
Cell cell(double v, int n) {
    const double s = v * n;
    const int i = std::min(int(s), n - 1);  // v * n may round up to n
    return {i, (i + 1) % n, s - i};
}

double lerp(double a, double b, double t) { return a + t * (b - a); }

// Interpolation 2: Catmull-Rom weights of the voxels at i − 1, i, i + 1 and i + 2 along one
// axis, with their indices. The neighbours wrap modulo n; POV-Ray takes i − 1 of voxel 0 in
// unsigned 64-bit arithmetic, so it lands on (2⁶⁴ − 1) mod n, not always on n − 1.
struct CubicAxis {
    int index[4];
    double weight[4];
};
CubicAxis cubic_axis(double v, int n) {
    const double s = v * n;
    const int i = std::min(int(s), n - 1);
    const double t = s - i, t2 = t * t, t3 = t2 * t;
    CubicAxis c;
    c.index[0] = i > 0 ? i - 1 : int(~uint64_t(0) % uint64_t(n));
    c.index[1] = i;
    c.index[2] = (i + 1) % n;
    c.index[3] = (i + 2) % n;
    c.weight[0] = (-t3 + 2 * t2 - t) / 2;
    c.weight[1] = (3 * t3 - 5 * t2 + 2) / 2;
    c.weight[2] = (-3 * t3 + 4 * t2 + t) / 2;
    c.weight[3] = (t3 - t2) / 2;
    return c;
}

double tricubic(const scene::pattern::DensityGrid& g, const glm::dvec3& p) {
    const CubicAxis x = cubic_axis(p.x, g.nx), y = cubic_axis(p.y, g.ny), z = cubic_axis(p.z, g.nz);
    double sum = 0;
    for (int k = 0; k < 4; ++k)
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 4; ++i)
                sum += z.weight[k] * y.weight[j] * x.weight[i] * g.at(x.index[i], y.index[j], z.index[k]);
    return std::max(sum, 0.0);  // measured: an undershoot is 0, an overshoot is kept
}

}  // namespace

double evaluate(const scene::pattern::Average&, const glm::dvec3&) { return 0.0; }

// POV-Ray's grey of the colour (0.297 r + 0.589 g + 0.114 b), the pigment evaluated at the
// pattern point; in single precision, as POV-Ray's colours are (white's grey is then exactly
// 1, which in double would be 0.9999999999999999).
double evaluate(const scene::pattern::PigmentPattern& k, const glm::dvec3& p) {
    const scene::Colour c = evaluate_pigment(k.pigment.get(), p);
    const float r = float(c.r), g = float(c.g), b = float(c.b);
    return 0.297f * r + 0.589f * g + 0.114f * b;
}

// The unit cube holds the grid; outside it the density is 0. Interpolation 1 blends the
// eight voxels around p with voxel i at i/n (not its centre), wrapping at the far faces.
double evaluate(const scene::pattern::DensityFile& k, const glm::dvec3& p) {
    const scene::pattern::DensityGrid& g = *k.grid;
    if (!(p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1 && p.z >= 0 && p.z < 1)) return 0;  // NaN too
    if (k.interpolate % 10 == 2) return tricubic(g, p);
    const Cell x = cell(p.x, g.nx), y = cell(p.y, g.ny), z = cell(p.z, g.nz);
    if (k.interpolate % 10 != 1) return g.at(x.i, y.i, z.i);
    auto plane = [&](int zi) {
        return lerp(lerp(g.at(x.i, y.i, zi), g.at(x.next, y.i, zi), x.t),
                    lerp(g.at(x.i, y.next, zi), g.at(x.next, y.next, zi), x.t), y.t);
    };
    return lerp(plane(z.i), plane(z.next), z.t);
}

// 1 inside the object, 0 outside (POV-Ray's Inside test, the object's own transforms, CSG and
// clipped_by applied). Each thread compiles an object's nodes once; an entry whose object has
// gone (a later frame reusing the address) is compiled again.
double evaluate(const scene::pattern::Object& k, const glm::dvec3& p) {
    if (!k.object) return 0;
    struct Compiled {
        std::weak_ptr<const scene::Object> source;
        NodeStore store;
        uint32_t root = 0;
    };
    thread_local std::unordered_map<const scene::Object*, Compiled> compiled;
    Compiled& c = compiled[k.object.get()];
    if (c.source.expired()) {
        c.store = NodeStore{};
        c.root = compile_object(c.store, *k.object, NodeContext{}, false);
        c.source = k.object;
    }
    return inside_node(c.store, c.root, p) ? 1.0 : 0.0;
}

// The function at the pattern point; POV-Ray keeps a value above 1 only as its fraction (1
// stays 1), and the pattern pipeline goes on from there (frequency, wrapping, wave).
double evaluate(const scene::pattern::Function& k, const glm::dvec3& p,
                const scene::Pattern& pattern) {
    if (!k.program) return 0;
    const double args[3] = {p.x, p.y, p.z};
    fn::Context context;
    context.host = &function_host();
    if (pattern.globals) context.noise_generator = pattern.globals->noise_generator;
    const double v = fn::evaluate(*k.program, args, context);
    return v > 1 ? std::fmod(v, 1.0) : v;
}

}  // namespace lumen::render
