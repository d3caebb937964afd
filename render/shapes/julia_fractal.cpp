// julia_fractal: POV-Ray's march and bisection. Which thin features a ray finds depends on
// where the steps land, so the rules are POV-Ray's (measured against its silhouettes): the
// steps are max(1/precision, estimate) in object space along the unit direction, the march
// starts 1e-7 in (2e-7 further when that point is inside), the bisection halves down to 1e-7,
// and the normal is computed from the orbit of the last point the bisection tested (entries
// past its escape are those of an earlier point of the same ray, as in POV-Ray's stack).
#include "render/shapes/julia_fractal.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "render/shapes/hypercomplex.hpp"

namespace lumen::render {

namespace {

using scene::JuliaAlgebra;
using scene::JuliaFunction;

// POV-Ray's MIN_ISECT_DEPTH: the tracer's nearest accepted hit (world distance).
constexpr double kMinIntersectionDepth = 1e-4;

// The hypercomplex estimate is used only while |z|^2 falls along the ray faster than this
// (POV-Ray's 1e-8 on half the slope).
constexpr double kJuliaSlopeTolerance = 2e-8;

// A bound on one ray's march (a huge precision makes tiny steps).
constexpr int kMaxMarchSteps = 1 << 20;

// The 4-D point of object point p on the slice.
// `z_from_y`: POV-Ray's inside test for the hypercomplex functions other than sqr, cube and
// reciprocal starts from (x, y, y) instead of (x, y, z), its slice w taken from that point
// too; its march does not (measured: the renders of exp, sin, cos, pwr only match so).
glm::dvec4 start_point(const JuliaFractalShape& s, const glm::dvec3& p, bool z_from_y = false) {
    const glm::dvec3 q(p.x, p.y, z_from_y ? p.y : p.z);
    const double w =
        (s.slice_distance - s.slice.x * q.x - s.slice.y * q.y - s.slice.z * q.z) / s.slice.w;
    return {q, w};
}

// Hypercomplex functions other than sqr, cube and reciprocal (see start_point).
bool general_function(const JuliaFractalShape& s) {
    return s.algebra == JuliaAlgebra::Hypercomplex && s.function != JuliaFunction::Sqr &&
           s.function != JuliaFunction::Cube && s.function != JuliaFunction::Reciprocal;
}

double norm2_of(const JuliaFractalShape& s, const glm::dvec4& z) {
    if (s.algebra == JuliaAlgebra::Quaternion) return glm::dot(z, z);
    return s.function == JuliaFunction::Sqr ? hypercomplex_sqr_norm2(z)
                                            : hypercomplex_norm2(s.function, z);
}

// One step z <- f(z) + c. For quaternion cubes, z^3 = (x (x^2 - 3d), v (3x^2 - d)).
glm::dvec4 next_iterate(const JuliaFractalShape& s, const glm::dvec4& z) {
    if (s.algebra == JuliaAlgebra::Quaternion) {
        const double d = z.y * z.y + z.z * z.z + z.w * z.w, x2 = z.x * z.x;
        if (s.function == JuliaFunction::Sqr) {
            const double t = 2 * z.x;
            return glm::dvec4(x2 - d, t * z.y, t * z.z, t * z.w) + s.c;
        }
        const double t = 3 * x2 - d;
        return glm::dvec4(z.x * (x2 - 3 * d), t * z.y, t * z.z, t * z.w) + s.c;
    }
    if (s.function == JuliaFunction::Sqr) return hypercomplex_sqr_step(z, s.c);
    return hypercomplex_step(s.function, z, s.c, Complex(s.exponent.x, s.exponent.y));
}

// POV-Ray's Iteration: inside unless |z|^2 exceeds the exit value before one of the steps;
// the iterates go to `orbit` (0 .. the escape or max_iteration).
bool iterate(const JuliaFractalShape& s, const glm::dvec3& p, glm::dvec4* orbit) {
    glm::dvec4 z = start_point(s, p, general_function(s));
    if (orbit) orbit[0] = z;
    for (int i = 1; i <= s.iterations; ++i) {
        if (norm2_of(s, z) > s.exit_value) return false;
        z = next_iterate(s, z);
        if (orbit) orbit[i] = z;
    }
    return true;
}

// POV-Ray's derivative chain for hypercomplex numbers, the true derivative only for sqr:
// z_0 g(z_1) ... g(z_N-1) (g: hypercomplex_chain_factor) times chain_scale(N). Its march and
// normals follow this chain (found by matching POV-Ray's renders of each function).
double chain_scale(const JuliaFractalShape& s, int n) {  // sqr's 2^N (2 when N = 0)
    if (s.function != JuliaFunction::Sqr) return 1.0;
    n = std::max(n, 1);
    // Exact either way; the shift spares a libm call per march step.
    return n < 63 ? double(uint64_t(1) << n) : std::ldexp(1.0, n);
}

// The gradient (halved) of |z_N|^2 with respect to (x, y, z), w held, for the chain D:
// z_N . D, z_N . D i and z_N . D j.
glm::dvec3 chain_gradient(const glm::dvec4& zn, const glm::dvec4& D) {
    return {glm::dot(zn, D), glm::dot(zn, glm::dvec4(-D.y, D.x, -D.w, D.z)),
            glm::dot(zn, glm::dvec4(-D.z, -D.w, D.x, D.y))};
}

// Hypercomplex numbers: |z|^2 over its rate of fall along u (from the chain above), used
// only when that lies between 1 and 30 steps, else the step. Measured against POV-Ray's
// silhouettes (|z|^2 itself, not its excess over the exit value; the 30 steps).
bool hypercomplex_estimate(const JuliaFractalShape& s, const glm::dvec3& p, const glm::dvec3& u,
                           double& estimate, glm::dvec4* orbit) {
    glm::dvec4 z = start_point(s, p);
    if (orbit) orbit[0] = z;
    glm::dvec4 chain = z;  // z_0 g(z_1) ... g(z_i-2)
    const Complex e(s.exponent.x, s.exponent.y);
    estimate = s.step;
    for (int i = 1; i <= s.iterations; ++i) {
        const double n2 = norm2_of(s, z);
        if (n2 > s.exit_value) {
            // The slope ignores w's change along the ray (measured, as for the normal).
            const double slope =
                -2 * glm::dot(chain_gradient(z * chain_scale(s, i - 1), chain), u);
            if (slope > kJuliaSlopeTolerance && n2 > s.step * slope &&
                n2 < 30 * s.step * slope)
                estimate = n2 / slope;
            return false;
        }
        if (i >= 2)  // sqr's factor is z itself: no call on the hot path
            chain = hypercomplex_product(
                s.function == JuliaFunction::Sqr ? z : hypercomplex_chain_factor(s.function, z, e),
                chain);
        z = next_iterate(s, z);
        if (orbit) orbit[i] = z;
    }
    return true;
}

// POV-Ray's D_Iteration: the same test, and for an escaped point the distance to march.
// Quaternions: the estimate ln|z_i|^2 / (2 |z'|) with |z'| = 2^i |z_0| ... |z_i-1| for sqr,
// ln|z_i|^2 / (3 |z'|) with |z'| = 3^i |z_0| ... |z_i-1| for cube (the iterates' norms, not
// their squares): both measured, POV-Ray's silhouettes are reproduced pixel for pixel.
// Inside points give the step.
bool iterate_estimate(const JuliaFractalShape& s, const glm::dvec3& p, const glm::dvec3& u,
                      double& estimate, glm::dvec4* orbit) {
    if (s.algebra == JuliaAlgebra::Hypercomplex)
        return hypercomplex_estimate(s, p, u, estimate, orbit);
    const bool cube = s.function == JuliaFunction::Cube;
    glm::dvec4 z = start_point(s, p);
    if (orbit) orbit[0] = z;
    double d2 = 1;
    for (int i = 1; i <= s.iterations; ++i) {
        const double n2 = glm::dot(z, z);
        if (n2 > s.exit_value) {
            // Only max(estimate, step) is used: where the tangent bound of ln n2 at the exit
            // value already puts the estimate below the step, the logarithm is spared.
            const double k = cube ? 1.0 / 3 : 0.5;
            const double bound = k * (s.log_exit + (n2 - s.exit_value) / s.exit_value);
            if (bound >= 0 && bound * bound * (1 + 1e-9) < s.step * s.step * d2 * (1 - 1e-9)) {
                estimate = 0;
                return false;
            }
            estimate = k * std::log(n2) / std::sqrt(d2);
            if (!(estimate >= 0)) estimate = 0;  // 0/0 or inf/inf: take the plain step
            return false;
        }
        d2 *= cube ? 9 * n2 : 4 * n2;
        z = next_iterate(s, z);
        if (orbit) orbit[i] = z;
    }
    estimate = s.step;
    return true;
}

// Keeps a running product finite without changing its direction.
template <class V> void rescale(V* rows, int n) {
    double big = 0;
    for (int r = 0; r < n; ++r)
        for (int k = 0; k < 4; ++k) big = std::max(big, std::fabs(rows[r][k]));
    if (big > 1e100 || (big < 1e-100 && big > 0))
        for (int r = 0; r < n; ++r) rows[r] *= 1 / big;
}

// The gradient of |z_N|^2 with respect to (x, y, z) of the 4-D start point, w held (POV-Ray
// leaves out w's dependence on the slice: measured, tilted slices shade the same).
glm::dvec3 orbit_normal(const JuliaFractalShape& s, const glm::dvec4* orbit) {
    const int n = std::max(s.iterations, 0);
    if (s.algebra == JuliaAlgebra::Quaternion) {
        glm::dvec4 rows[3] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
        for (int i = 0; i < n; ++i) {
            const glm::dvec4& z = orbit[i];
            for (glm::dvec4& v : rows) {
                if (s.function == JuliaFunction::Sqr) {  // z v + v z
                    v = {z.x * v.x - z.y * v.y - z.z * v.z - z.w * v.w, z.x * v.y + z.y * v.x,
                         z.x * v.z + z.z * v.x, z.x * v.w + z.w * v.x};
                } else {  // v z^2 + z v z + z^2 v
                    const glm::dvec4 z2 = quaternion_product(z, z);
                    v = quaternion_product(v, z2) +
                        quaternion_product(quaternion_product(z, v), z) +
                        quaternion_product(z2, v);
                }
            }
            rescale(rows, 3);
        }
        const glm::dvec4& zn = orbit[n];
        return {glm::dot(rows[0], zn), glm::dot(rows[1], zn), glm::dot(rows[2], zn)};
    }
    // Hypercomplex: the chain (see chain_scale) is one number D; d z_N = D dh.
    const Complex e(s.exponent.x, s.exponent.y);
    glm::dvec4 D = orbit[0];
    for (int i = 1; i < n; ++i) {
        D = hypercomplex_product(hypercomplex_chain_factor(s.function, orbit[i], e), D);
        rescale(&D, 1);
    }
    return chain_gradient(orbit[n], D);
}

// The ray's span in the bounding sphere (unit direction u), as POV-Ray clips it.
bool clip_to_sphere(const JuliaFractalShape& s, const glm::dvec3& o, const glm::dvec3& u,
                    double& kmin, double& kmax) {
    const double oc2 = glm::dot(o, o), closest = -glm::dot(o, u);
    if (oc2 >= s.radius2 && closest < 1e-10) return false;
    const double half2 = s.radius2 - oc2 + closest * closest;
    if (!(half2 > 1e-10)) return false;
    const double half = std::sqrt(half2);
    kmin = closest - half;
    kmax = closest + half;
    return true;
}

// The iteration stack of one ray: max_iteration + 1 iterates.
class Orbit {
public:
    explicit Orbit(int iterations) {
        const size_t n = size_t(std::max(iterations, 0)) + 1;
        if (n > small_.size()) {
            big_.assign(n, glm::dvec4(0));
            data_ = big_.data();
        } else {
            std::fill_n(data_, n, glm::dvec4(0));  // only what is used: this runs per ray
        }
    }
    glm::dvec4* data() { return data_; }

private:
    std::array<glm::dvec4, 65> small_;
    std::vector<glm::dvec4> big_;
    glm::dvec4* data_ = small_.data();
};

// POV-Ray's search along o + k u (u unit) from k = `start` up to `depth_max`: the depth k of
// the first change of state, the normal there.
// A crossing found to lie below `unwanted` is dropped early (false); past `outside_beyond`
// no point is inside (the grid), so a march from outside ends there.
bool first_crossing(const JuliaFractalShape& s, const glm::dvec3& o, const glm::dvec3& u,
                    double start, double depth_max, double unwanted, double outside_beyond,
                    double& depth, glm::dvec3& normal) {
    // The step is 1/precision in object space whatever the transform (measured: scaling
    // the object changes nothing in POV-Ray's march).
    const double step = s.step;
    // One iteration stack for the whole search, as POV-Ray's: the normal's orbit keeps the
    // entries of earlier points past where the last one escaped.
    Orbit orbit(s.iterations);
    // Where the inside test and the march agree the reported point is inside, its orbit
    // complete: only its own is needed, and the steps before need not keep theirs.
    glm::dvec4* const kept = general_function(s) ? orbit.data() : nullptr;
    depth = start;
    glm::dvec3 next = o + depth * u;
    double dist = 0, dist_next = 0;
    bool current_in = iterate_estimate(s, next, u, dist, kept);
    if (current_in) {  // starting inside (a shadow or CSG ray): move off the start
        next += 2 * kJuliaTolerance * u;
        depth += 2 * kJuliaTolerance;
        if (depth > depth_max) return false;
        current_in = iterate_estimate(s, next, u, dist, kept);
    }
    // March: each step at least `step`, until the state changes; `at` trails one step.
    if (!current_in) depth_max = std::min(depth_max, outside_beyond);
    glm::dvec3 at = next;
    for (int steps = 0;; ++steps) {
        if (steps == kMaxMarchSteps) return false;
        dist = std::max(dist, step);
        depth += dist;
        if (depth > depth_max) return false;
        at = next;
        next += dist * u;
        if (iterate_estimate(s, next, u, dist_next, kept) != current_in) break;
        dist = dist_next;
    }
    depth -= dist;
    // Bisect the step that crossed: `at` stays on the starting side.
    bool last = !current_in;
    while (dist > kJuliaTolerance) {
        // The depth reported lies in [depth, depth + dist] (the step before this halving).
        if (depth + dist < unwanted) return false;
        dist *= 0.5;
        const glm::dvec3 mid = at + dist * u;
        last = iterate(s, mid, kept);
        if (last == current_in) {
            at = mid;
            depth += dist;
            if (depth > depth_max) return false;
        }
    }
    // The normal comes from the orbit of the reported point, iterated again unless the last
    // test was of that point (as POV-Ray's stack holds it).
    if (!current_in) {  // entering: report the first point found inside
        depth += dist;
        at += dist * u;
        iterate(s, at, orbit.data());
    } else if (last != current_in || !kept) {
        iterate(s, at, orbit.data());
    }
    normal = orbit_normal(s, orbit.data());
    return true;
}

}  // namespace

JuliaFractalShape make_julia_fractal(const scene::JuliaFractal& j) {
    JuliaFractalShape s;
    s.algebra = j.algebra;
    s.function = j.function;
    const glm::dvec4 c(j.c[0], j.c[1], j.c[2], j.c[3]);
    s.c = c;
    s.exponent = j.exponent;
    s.iterations = std::max(j.max_iteration, 0);
    s.step = 1 / std::max(j.precision, 1.0);
    s.slice = glm::dvec4(j.slice[0], j.slice[1], j.slice[2], j.slice[3]);
    if (!(std::fabs(s.slice.w) >= 1e-10)) s.iterations = -1;  // the reader refuses it
    s.slice_distance = j.slice_distance;
    s.csg_child = j.csg_child;
    const double r = j.bound_radius();
    s.radius2 = r * r;
    s.exit_value = j.exit_value();
    s.log_exit = std::log(s.exit_value) * (1 + 1e-12) + 1e-300;  // rounded up
    s.grid = JuliaGrid::build(s);
    return s;
}

bool intersect(const JuliaFractalShape& s, const LocalRay& r, double tmin, double tmax,
               ShapeHit& h) {
    if (s.iterations < 0) return false;
    const double len = glm::length(r.d);
    if (!(len > 0) || !std::isfinite(len)) return false;
    const glm::dvec3 u = r.d / len;
    double kmin = 0, kmax = 0;
    if (!clip_to_sphere(s, r.o, u, kmin, kmax)) return false;
    kmax = std::min(kmax, tmax * len);
    if (kmax < kJuliaTolerance) return false;
    // POV-Ray marches from 1e-7 whatever the ray's minimum depth. A stand-alone fractal
    // reports only its first crossing, which the tracer drops when it is nearer than 1e-4:
    // then the object is not hit at all (a shadow ray leaving the surface it starts on is not
    // shadowed by the parts beyond; measured). A CSG child lists its further crossings too:
    // lumen marches on from tmin for them (POV-Ray's list repeats the first depth at points
    // further in before it reaches them; that is not reproduced).
    const double start = std::max(kmin, kJuliaTolerance);
    // A first crossing this near is not a hit (below), so its search can stop once it is
    // known to lie there: most shadow rays leaving the surface end so.
    const double unwanted = s.csg_child ? 0 : std::min(tmin, kMinIntersectionDepth) * len;
    double outside_beyond = kmax;
    if (s.grid) {
        double last = 1;
        if (!s.grid->maybe_span(r.o + start * u, r.o + kmax * u, last)) return false;
        outside_beyond = start + (kmax - start) * last * (1 + 1e-9);
    }
    double depth = 0;
    glm::dvec3 normal;
    if (!first_crossing(s, r.o, u, start, kmax, unwanted, outside_beyond, depth, normal))
        return false;
    if (!(depth / len > tmin) &&
        ((!s.csg_child && depth / len < kMinIntersectionDepth) ||
         !first_crossing(s, r.o, u, std::max(start, tmin * len), kmax, 0, outside_beyond, depth,
                         normal)))
        return false;
    const double t = depth / len;
    if (!(t > tmin) || !(t < tmax)) return false;
    h.t = t;
    h.normal = normal;
    const double n2 = glm::dot(normal, normal);
    if (!(n2 > 0) || !std::isfinite(n2)) h.normal = -u;
    return true;
}

bool inside(const JuliaFractalShape& s, const glm::dvec3& p) {
    if (s.iterations < 0) return false;
    if (glm::dot(p, p) > s.radius2) return false;  // outside the bounding sphere
    if (s.grid && !s.grid->may_contain(p)) return false;
    return iterate(s, p, nullptr);
}

Aabb bounds(const JuliaFractalShape& s) {
    if (s.iterations < 0) return {};
    const double r = std::sqrt(s.radius2);
    return {glm::dvec3(-r), glm::dvec3(r)};
}

}  // namespace lumen::render
