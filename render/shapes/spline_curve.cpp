// Spline segments of prism and lathe: the coefficients are POV-Ray's (linear, quadratic
// through three points, Catmull-Rom cubic, Bezier), so the curves are its curves.
#include "render/shapes/spline_curve.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "render/polynomial.hpp"

namespace lumen::render {

CurveSegment spline_segment(scene::SplineKind kind, const glm::dvec2* p, bool backward_bezier) {
    CurveSegment s;
    switch (kind) {
        case scene::SplineKind::Linear:
            s.c = p[1] - p[0];
            s.d = p[0];
            break;
        case scene::SplineKind::Quadratic:  // from p[1] to p[2]
            s.b = 0.5 * p[0] - p[1] + 0.5 * p[2];
            s.c = 0.5 * (p[2] - p[0]);
            s.d = p[1];
            break;
        case scene::SplineKind::Cubic:  // Catmull-Rom from p[1] to p[2]
            s.a = -0.5 * p[0] + 1.5 * p[1] - 1.5 * p[2] + 0.5 * p[3];
            s.b = p[0] - 2.5 * p[1] + 2.0 * p[2] - 0.5 * p[3];
            s.c = 0.5 * (p[2] - p[0]);
            s.d = p[1];
            break;
        case scene::SplineKind::Bezier: {
            const glm::dvec2 q0 = backward_bezier ? p[3] : p[0], q1 = backward_bezier ? p[2] : p[1],
                             q2 = backward_bezier ? p[1] : p[2], q3 = backward_bezier ? p[0] : p[3];
            s.a = q3 - 3.0 * q2 + 3.0 * q1 - q0;
            s.b = 3.0 * q2 - 6.0 * q1 + 3.0 * q0;
            s.c = 3.0 * q1 - 3.0 * q0;
            s.d = q0;
            break;
        }
    }
    // The box: both ends and the interior extrema, where S'(w) = 0.
    s.lo = glm::min(s.at(0), s.at(1));
    s.hi = glm::max(s.at(0), s.at(1));
    for (int axis = 0; axis < 2; ++axis) {
        const double slope[3] = {s.c[axis], 2 * s.b[axis], 3 * s.a[axis]};
        double w[2];
        const int n = solve_polynomial_in(slope, 2, 0, 1, w);
        for (int i = 0; i < n; ++i) {
            const double v = s.at(w[i])[axis];
            s.lo[axis] = std::min(s.lo[axis], v);
            s.hi[axis] = std::max(s.hi[axis], v);
        }
    }
    return s;
}

bool inside_curve(const Curve& curve, const glm::dvec2& q, double y_pad) {
    if (curve.segments.empty() || q.x > curve.hi.x || q.y < curve.lo.y - y_pad ||
        q.y > curve.hi.y + y_pad)
        return false;
    int count = 0;
    for (const CurveSegment& s : curve.segments) {
        if (q.y < s.lo.y - y_pad || q.y > s.hi.y + y_pad || q.x > s.hi.x) continue;
        double c[4];
        s.coefficients(1, c);
        c[0] -= q.y;
        if (q.x < s.lo.x - 1e-9 * (1 + std::abs(s.lo.x))) {
            // Every crossing lies to the right: only their number matters.
            count += count_roots_in(c, significant_degree(c, 3), 0, 1);
            continue;
        }
        double w[3];
        const int n = solve_significant_in(c, 3, 0, 1, w);
        for (int i = 0; i < n; ++i)
            if (s.at(w[i]).x >= q.x) ++count;
    }
    return count % 2 == 1;
}

Curve make_curve(scene::SplineKind kind, const std::vector<glm::dvec2>& points,
                 const std::vector<int>& starts, bool backward_bezier) {
    Curve curve;
    for (int i : starts) {
        CurveSegment s = spline_segment(kind, points.data() + i, backward_bezier);
        curve.lo = curve.segments.empty() ? s.lo : glm::min(curve.lo, s.lo);
        curve.hi = curve.segments.empty() ? s.hi : glm::max(curve.hi, s.hi);
        curve.segments.push_back(s);
    }
    const glm::dvec2 size = curve.hi - curve.lo;
    const double hair = 1e-7 * (1 + std::max(size.x, size.y));
    for (CurveSegment& s : curve.segments) {
        glm::dvec2 t = s.tangent(0.5);
        if (!(glm::length(t) > 0)) t = s.at(1) - s.at(0);
        if (!(glm::length(t) > 0)) continue;
        const glm::dvec2 right = glm::normalize(glm::dvec2(t.y, -t.x));
        s.outward = inside_curve(curve, s.at(0.5) + hair * right) ? -1 : 1;
    }
    return curve;
}

}  // namespace lumen::render
