// Normal perturbation, following POV-Ray 3.7 (measured against povray renders):
// * the normal enters the pattern's space through the transpose of each transform's forward
//   matrix and leaves through the transpose of its inverse, normalised on the way in and out
//   (with no_bump_scale it is not, so a smaller pattern tilts it more);
// * kinds with a form of their own (render/patterns/normal_forms.hpp) add it there;
// * a normal_map picks the entries around the pattern's value; each perturbs the pattern-space
//   normal at the pattern-space point and the two results are blended (POV ignores the
//   parent's amount and accuracy then);
// * every other pattern is differenced: its value, through the slope_map if any, sampled at
//   four points of a tetrahedron `accuracy` around the point, each leaning the normal away
//   from its direction by amount * -5 * (0.02 / accuracy) times the value.
#include "render/normal.hpp"

#include <cmath>
#include <variant>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "render/pattern.hpp"
#include "render/patterns/normal_forms.hpp"
#include "scene/normal_forms.hpp"

namespace lumen::render {
namespace {

// The sample directions of the finite differences, as POV writes them.
constexpr glm::dvec3 kTetrahedron[4] = {{0.942809041, -0.333333333, 0},
                                        {-0.471404521, -0.333333333, 0.816496581},
                                        {-0.471404521, -0.333333333, -0.816496581},
                                        {0, 1, 0}};

glm::dvec3 normalised(const glm::dvec3& n) {
    const double len = glm::length(n);
    return len > 0 ? n / len : n;
}

// World -> pattern space: the transforms latest first, each through its forward matrix's
// transpose.
glm::dvec3 to_pattern_normal(const scene::Normal& normal, glm::dvec3 n) {
    const bool scale = !normal.no_bump_scale;
    if (scale) n = normalised(n);
    const auto& steps = normal.pattern.steps.steps;
    for (auto it = steps.rbegin(); it != steps.rend(); ++it)
        if (const auto* t = std::get_if<scene::Transform>(&*it); t && !t->is_identity())
            n = glm::transpose(glm::dmat3(t->m)) * n;
    return scale ? normalised(n) : n;
}

// Pattern -> world space: the transforms in the order written, each through its inverse's
// transpose. With no_bump_scale the result keeps its length (a normal_map blends it so; the
// renderer normalises the final normal).
glm::dvec3 to_world_normal(const scene::Normal& normal, glm::dvec3 n) {
    const bool scale = !normal.no_bump_scale;
    if (scale) n = normalised(n);
    for (const scene::PatternStep& step : normal.pattern.steps.steps)
        if (const auto* t = std::get_if<scene::Transform>(&step); t && !t->is_identity())
            n = glm::transpose(glm::dmat3(t->inv)) * n;
    return scale ? normalised(n) : n;
}

void perturb(const scene::Normal& normal, glm::dvec3& n, const glm::dvec3& p);

// Adds the differenced slope of the pattern's value at pattern-space point tp.
void add_slope(const scene::Normal& normal, const glm::dvec3& tp, glm::dvec3& n) {
    const double k = normal.amount * -5.0 * (0.02 / normal.accuracy);
    for (const glm::dvec3& dir : kTetrahedron) {
        double v = pattern_value_at(normal.pattern, tp + normal.accuracy * dir);
        if (!normal.slope_map.empty()) v = slope_height(normal.slope_map, v);
        n += (v * k) * dir;
    }
}

// normal_map (or list entries): the entries around the pattern's value, blended.
void blend_entries(const scene::Normal& normal, const glm::dvec3& tp, glm::dvec3& n) {
    const BlendWeights b = blend_weights(normal.normal_map, pattern_value_at(normal.pattern, tp));
    const scene::Normal* lower = normal.normal_map[b.lower].item.get();
    glm::dvec3 lo = n;
    if (lower) perturb(*lower, lo, tp);
    if (b.upper_weight == 0) {
        n = lo;
        return;
    }
    const scene::Normal* upper = normal.normal_map[b.upper].item.get();
    glm::dvec3 hi = n;
    if (upper) perturb(*upper, hi, tp);
    n = (1 - b.upper_weight) * lo + b.upper_weight * hi;
}

// average: the normal_map's normals weighted by their values (single precision in POV).
void average_entries(const scene::Normal& normal, const glm::dvec3& tp, glm::dvec3& n) {
    glm::dvec3 sum(0);
    float total = 0;
    for (const auto& entry : normal.normal_map) {
        glm::dvec3 each = n;
        if (entry.item) perturb(*entry.item, each, tp);
        const float w = float(entry.value);
        sum += double(w) * each;
        total += w;
    }
    if (total != 0) n = sum / double(total);
}

// Perturbs n (in the space of p, not normalised) by `normal` at p.
void perturb(const scene::Normal& normal, glm::dvec3& n, const glm::dvec3& p) {
    const scene::Pattern& pattern = normal.pattern;
    if (pattern.is_plain()) return;
    n = to_pattern_normal(normal, n);
    const glm::dvec3 tp = pattern_point(pattern, p);
    std::visit(
        [&](const auto& kind) {
            using Kind = std::decay_t<decltype(kind)>;
            using Form = scene::NormalForm<Kind>;
            if constexpr (std::is_same_v<Kind, scene::pattern::Average>) {
                average_entries(normal, tp, n);
            } else if constexpr (Form::dedicated) {
                // Not rendered: reported unsupported by the interp, never reaches a render.
                if constexpr (Form::rendered) apply_form(kind, normal, tp, n);
            } else if (!normal.normal_map.empty()) {
                blend_entries(normal, tp, n);
            } else {
                add_slope(normal, tp, n);
            }
        },
        pattern.kind);
    n = to_world_normal(normal, n);
}

bool usable(const glm::dvec3& n) {
    const double len2 = glm::dot(n, n);
    return len2 > 0 && std::isfinite(len2);
}

}  // namespace

glm::dvec3 perturbed_normal(const scene::Normal& normal, const glm::dvec3& raw,
                            const glm::dvec3& p) {
    glm::dvec3 n = raw;
    perturb(normal, n, p);  // unit length unless degenerate or no_bump_scale
    if (!usable(n)) return raw;
    return normal.no_bump_scale ? glm::normalize(n) : n;
}

double slope_height(const scene::SlopeMap& map, double v) {
    if (map.empty()) return v;
    const BlendWeights b = blend_weights(map, v);
    const glm::dvec2 lo = map[b.lower].item;
    if (b.upper_weight == 0 || b.lower == b.upper) return lo.x;
    const glm::dvec2 hi = map[b.upper].item;
    const double t = b.upper_weight;
    const double h0 = lo.x, s0 = lo.y, h1 = hi.x, s1 = hi.y;
    return t * t * t * (s0 + s1 + 2 * (h0 - h1)) - t * t * (2 * s0 + s1 + 3 * (h0 - h1)) +
           t * s0 + h0;
}

}  // namespace lumen::render
