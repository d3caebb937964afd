// sphere_sweep: the union of the spheres whose centre c(s) and radius r(s) follow the spline
// through the listed spheres, one polynomial segment per spline piece (s in [0, 1]).
//
// What POV-Ray 3.7 does, probed with povray (renders, min_extent/max_extent, its errors):
//   linear_spline: N - 1 segments from sphere i to sphere i + 1, centre and radius linear;
//   b_spline:      N - 3 segments of the uniform cubic B-spline (from near sphere 2 to near
//                  sphere N - 1; the first and last spheres steer the curve only);
//   cubic_spline:  N - 3 Catmull-Rom segments through spheres 2 .. N - 1.
//   At least 2 spheres for linear_spline, 4 for the others ("Too few modeling spheres for
//   interpolation type", at the count); the spline keyword is required, once ("Invalid
//   type of interpolation"); N is truncated; commas are optional; tolerance (default 1e-6)
//   comes right after the spheres, never among the modifiers; sturm is refused.
//   A radius enters as r^2: one running from 0.3 to -0.5 narrows to a point and widens
//   again; a zero radius ends in a cone's tip; coincident spheres are that sphere; a sphere
//   holding its neighbour hides the tube between them.
//   POV-Ray's box is each listed centre -/+ its radius as written (twice it for
//   cubic_spline); all-negative radii invert that box and nothing is drawn.
//   At the default tolerance POV-Ray leaves dark specks on spline sweeps (self-shadowing,
//   as its manual warns); this solver does not, so probe scenes raise the tolerance.
//
// Along a ray o + t d, the sphere of parameter s is met where the quadratic
// g(t, s) = |o + t d - c(s)|^2 - r(s)^2 has real roots t_in(s) <= t_out(s), i.e. where its
// discriminant D(s) >= 0. Over each connected s-range of D >= 0 the intervals
// [t_in, t_out] vary continuously, so together they are the one interval
// [min t_in, max t_out]. Those extremes lie at the ends of the range or where
// dg/ds = 0 on the sphere: dg/ds is linear in t, and putting its root into g gives a
// polynomial P(s) (degree 2 for a linear segment, 10 for a cubic one) whose roots in the
// range are the only other candidates. The sweep along the ray is the union of these
// intervals over all segments; a hit is the first boundary of that union past the ray's
// start, so internal surfaces between segments are never reported.
#pragma once
#include <vector>

#include "render/bvh.hpp"
#include "render/shapes/shape.hpp"

namespace lumen::render {

struct SweepSegment {
    int degree = 1;            // 1 (linear) or 3 (cubic)
    glm::dvec3 c[4]{};         // centre c(s) = c[0] + c[1] s + c[2] s^2 + c[3] s^3
    double r[4]{};             // radius, the same way
    Aabb box;                  // holds every sphere of the segment
};

struct SphereSweepShape {
    std::vector<SweepSegment> segments;  // in the order of tree.order()
    Bvh tree;
    Aabb box;
    double tolerance = 1e-6;  // hits nearer than this to the ray's start are ignored
    bool valid = false;
};

// The segments of a sweep, in spline order (also used by tests).
std::vector<SweepSegment> sweep_segments(const scene::SphereSweep& s);

SphereSweepShape make_sphere_sweep(const scene::SphereSweep& s);
bool intersect(const SphereSweepShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
bool inside(const SphereSweepShape& s, const glm::dvec3& p);
inline Aabb bounds(const SphereSweepShape& s) { return s.box; }
inline Aabb solid_bounds(const SphereSweepShape& s) { return s.box; }

template <>
struct ShapeTraits<scene::SphereSweep>
    : PreparedBy<scene::SphereSweep, SphereSweepShape, make_sphere_sweep> {
    static bool bake(const scene::SphereSweep&, const scene::Transform&, SphereSweepShape&) {
        return false;
    }
};

}  // namespace lumen::render
