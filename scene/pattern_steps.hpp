// A pattern's transforms and warps, one ordered list as POV-Ray applies them. Measured with
// povray 3.7: transforms and `warp { }` blocks act in the order written, consecutive
// transforms compose, and the pattern's own (classic) `turbulence` acts first, before every
// transform and warp wherever it is written (`turbulence 0.5 scale 4`, `scale 4 turbulence
// 0.5` and `warp { turbulence 0.5 } scale 4` render the same), its octaves/omega/lambda
// editing that one turbulence wherever they are written.
#pragma once
#include <variant>
#include <vector>

#include <glm/vec3.hpp>

#include "base/source.hpp"
#include "scene/transform.hpp"

namespace lumen::scene {

struct TurbulenceParams {
    glm::dvec3 amount{0, 0, 0};  // 0 = none
    int octaves = 6;
    double omega = 0.5, lambda = 2.0;
    template <class Self, class F> static void fields(Self& s, F&& f) {
        f("turbulence", s.amount);
        f("octaves", s.octaves);
        f("omega", s.omega);
        f("lambda", s.lambda);
    }
};

namespace warp {

// The pattern's `turbulence` keyword; always the list's first step. It displaces the point in
// the pattern's own space, except for marble and wood, which take it into their formula.
struct ClassicTurbulence : TurbulenceParams {};
// `warp { turbulence <v> [octaves n] [omega f] [lambda f] }`.
struct Turbulence : TurbulenceParams {
    SourceLoc loc;
};
// `warp { repeat <axis> [offset <v>] [flip <v>] }`.
struct Repeat {
    glm::dvec3 direction{0, 0, 0}, offset{0, 0, 0}, flip{0, 0, 0};
    SourceLoc loc;
    template <class Self, class F> static void fields(Self& s, F&& f) {
        f("repeat", s.direction);
        f("offset", s.offset);
        f("flip", s.flip);
    }
};
// `warp { black_hole <centre>, radius [falloff] [strength] [repeat <v>] [turbulence <v>]
// [inverse] [type n] }`. With `repeat`, the interp has already raised the centre and the
// repeat on each repeated axis as POV-Ray does (centre >= radius, repeat >= centre + radius +
// turbulence); a repeat component below 1e-10 leaves that axis unrepeated.
struct BlackHole {
    glm::dvec3 centre{0, 0, 0};
    double radius = 1, falloff = 2, strength = 1;
    glm::dvec3 repeat{0, 0, 0}, turbulence{0, 0, 0};
    bool inverse = false;
    int type = 0;  // POV-Ray 3.7 has only type 0; any other leaves the point as it is
    SourceLoc loc;
    template <class Self, class F> static void fields(Self& s, F&& f) {
        f("black_hole", s.centre);
        f("radius", s.radius);
        f("falloff", s.falloff);
        f("strength", s.strength);
        f("repeat", s.repeat);
        f("turbulence", s.turbulence);
        f("inverse", s.inverse);
        f("type", s.type);
    }
};
// `warp { cylindrical | spherical | toroidal [orientation <v>] [dist_exp f]
// [major_radius f (toroidal)] }`, `warp { planar [<v>, offset] }` and `warp { cubic }`:
// mapping warps that wrap the pattern around a shape. `orientation` (planar's <v>) is
// normalised by the interp.
struct Mapping {
    enum class Shape { Cylindrical, Spherical, Toroidal, Planar, Cubic } shape{};
    glm::dvec3 orientation{0, 0, 1};
    double dist_exp = 0, major_radius = 1;
    double offset = 0;  // planar: the depth every point gets
    SourceLoc loc;
    template <class Self, class F> static void fields(Self& s, F&& f) {
        f("orientation", s.orientation);
        f("dist_exp", s.dist_exp);
        f("major_radius", s.major_radius);
        f("offset", s.offset);
    }
};

}  // namespace warp

using PatternStep = std::variant<Transform, warp::ClassicTurbulence, warp::Turbulence,
                                 warp::Repeat, warp::BlackHole, warp::Mapping>;

// Steps in the order they act on the pattern; a world point is mapped into pattern space
// through them last to first.
struct PatternSteps {
    std::vector<PatternStep> steps;

    // Appends a transform, composing it with a transform that ends the list.
    void add_transform(const Transform& t) {
        if (!steps.empty())
            if (auto* last = std::get_if<Transform>(&steps.back())) {
                *last = last->then(t);
                return;
            }
        steps.push_back(t);
    }
    // The classic turbulence, created at the front of the list on first use.
    TurbulenceParams& classic_turbulence() {
        if (steps.empty() || !std::holds_alternative<warp::ClassicTurbulence>(steps.front()))
            steps.insert(steps.begin(), warp::ClassicTurbulence{});
        return std::get<warp::ClassicTurbulence>(steps.front());
    }
    const TurbulenceParams* classic_turbulence() const {
        if (steps.empty()) return nullptr;
        return std::get_if<warp::ClassicTurbulence>(&steps.front());
    }
    // All transform steps composed, in order (the pattern's placement when it has no warps).
    Transform composed_transform() const {
        Transform total;
        bool first = true;
        for (const PatternStep& s : steps)
            if (const auto* t = std::get_if<Transform>(&s)) {
                total = first ? *t : total.then(*t);
                first = false;
            }
        return total;
    }
    bool has_warps() const {
        for (const PatternStep& s : steps)
            if (!std::holds_alternative<Transform>(s) &&
                !std::holds_alternative<warp::ClassicTurbulence>(s))
                return true;
        return false;
    }
};

}  // namespace lumen::scene
