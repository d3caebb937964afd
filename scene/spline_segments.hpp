// Which points make each segment of a prism's or a lathe's spline, as POV-Ray walks them.
// The interpreter uses the walk to check closure (a located error or warning), the renderer
// to build the segments' cubics, so both see the same segments.
#pragma once
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "scene/shapes.hpp"

namespace lumen::scene {

// How many points one segment reads, starting at its first index.
inline int points_per_segment(SplineKind k) {
    switch (k) {
        case SplineKind::Linear: return 2;
        case SplineKind::Quadratic: return 3;
        case SplineKind::Cubic: case SplineKind::Bezier: return 4;
    }
    return 2;
}

struct SplineWalk {
    std::vector<int> starts;  // first point index of each segment
    bool closed = true;       // every sub-shape ended on its first point
};

// POV-Ray's closing test between two points.
inline bool same_point(const glm::dvec2& a, const glm::dvec2& b) {
    return glm::length(a - b) < 1e-10;
}

// A prism's segments. Linear, quadratic and cubic splines run from point i (linear) or i+1 to
// the next, one point on per segment; when a segment ends on its sub-shape's first curve
// point, the walk jumps past the closing points (the closing point itself, and for cubic the
// trailing control point) and a new sub-shape starts. Bezier segments are groups of four,
// each ending where the next begins or closing its sub-shape.
inline SplineWalk prism_walk(SplineKind kind, const std::vector<glm::dvec2>& p) {
    SplineWalk walk;
    const int n = static_cast<int>(p.size()), per = points_per_segment(kind);
    if (kind == SplineKind::Bezier) {
        int first = 0;
        for (int i = 0; i + 3 < n; i += 4) {
            walk.starts.push_back(i);
            if (same_point(p[i + 3], p[first])) first = i + 4;
            else if (i + 4 >= n || !same_point(p[i + 3], p[i + 4])) walk.closed = false;
        }
        if (first < n) walk.closed = false;
        return walk;
    }
    const int lead = kind == SplineKind::Linear ? 0 : 1;  // index of the first curve point
    const int jump = kind == SplineKind::Linear ? 1 : kind == SplineKind::Quadratic ? 2 : 3;
    int first = lead, i = 0;
    walk.closed = false;
    while (i + per - 1 < n) {
        walk.starts.push_back(i);
        const int end = i + lead + 1;  // where this segment ends
        if (same_point(p[end], p[first])) {
            i += 1 + jump;
            first = i + lead;
            walk.closed = true;
        } else {
            ++i;
            walk.closed = false;
        }
    }
    // Points left over after the last closed sub-shape leave it unclosed too (measured: a
    // closed cubic outline followed by three more points is "not closed").
    walk.closed = walk.closed && i == n;
    return walk;
}

// A lathe's segments: every run of consecutive points (bezier: groups of four), no closing.
inline SplineWalk lathe_walk(SplineKind kind, const std::vector<glm::dvec2>& p) {
    SplineWalk walk;
    const int n = static_cast<int>(p.size()), per = points_per_segment(kind);
    const int step = kind == SplineKind::Bezier ? 4 : 1;
    for (int i = 0; i + per - 1 < n; i += step) walk.starts.push_back(i);
    return walk;
}

}  // namespace lumen::scene
