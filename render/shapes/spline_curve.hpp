// The 2-D spline segments of prism and lathe as POV-Ray builds them: each a cubic
// S(w) = ((a w + b) w + c) w + d for w in [0, 1], and the even-odd test over them that the
// prism's caps and inside, and the lathe's inside, share.
#pragma once
#include <vector>

#include <glm/vec2.hpp>

#include "scene/shapes.hpp"

namespace lumen::render {

struct CurveSegment {
    glm::dvec2 a{0}, b{0}, c{0}, d{0};
    glm::dvec2 lo{0}, hi{0};  // the curve's box over w in [0, 1]
    double outward = 1;       // +1: (S'.y, -S'.x) points out of the enclosed region
    glm::dvec2 at(double w) const { return ((a * w + b) * w + c) * w + d; }
    glm::dvec2 tangent(double w) const { return (3.0 * a * w + 2.0 * b) * w + c; }
    // The coefficients of one coordinate (0: x, 1: y), lowest power first.
    void coefficients(int axis, double out[4]) const {
        out[0] = d[axis], out[1] = c[axis], out[2] = b[axis], out[3] = a[axis];
    }
};

// The segment read from p[0..] (as many points as the spline kind reads). A prism's Bezier
// segment runs backward (w = 0 at its last point), a lathe's forward, as in POV-Ray.
CurveSegment spline_segment(scene::SplineKind kind, const glm::dvec2* p, bool backward_bezier);

struct Curve {
    std::vector<CurveSegment> segments;
    glm::dvec2 lo{0}, hi{0};  // box of every segment
};

// The segments starting at `starts` (scene/spline_segments.hpp), with their boxes and the
// side each one faces out on (by the even-odd test a hair beside its middle).
Curve make_curve(scene::SplineKind kind, const std::vector<glm::dvec2>& points,
                 const std::vector<int>& starts, bool backward_bezier);

// Whether q is inside the curve by POV-Ray's even-odd count: segments whose y range (widened
// by y_pad) holds q.y contribute each root of S.y(w) = q.y in [0, 1] with S.x(w) >= q.x.
bool inside_curve(const Curve& curve, const glm::dvec2& q, double y_pad = 0);

}  // namespace lumen::render
