#include "render/normal_frame.hpp"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "render/normal.hpp"

namespace lumen::render {
namespace {

glm::dvec3 normalised(const glm::dvec3& n) {
    const double len = glm::length(n);
    return len > 0 ? n / len : n;
}

}  // namespace

NormalFrame NormalFrame::of(const scene::Pattern& pattern) {
    NormalFrame f = none();
    const auto& steps = pattern.steps.steps;
    for (auto it = steps.rbegin(); it != steps.rend(); ++it)
        if (const auto* t = std::get_if<scene::Transform>(&*it); t && !t->is_identity()) {
            f.in = glm::transpose(glm::dmat3(t->m)) * f.in;
            f.identity = false;
        }
    if (f.identity) return f;
    for (const scene::PatternStep& step : steps)
        if (const auto* t = std::get_if<scene::Transform>(&step); t && !t->is_identity())
            f.out = glm::transpose(glm::dmat3(t->inv)) * f.out;
    return f;
}

NormalFrame NormalFrame::then(const NormalFrame& inner) const {
    if (inner.identity) return *this;
    if (identity) return inner;
    return {inner.in * in, out * inner.out, false};
}

glm::dvec3 framed_normal(const scene::Normal& normal, const glm::dvec3& raw,
                         const glm::dvec3& p, const NormalFrame& frame) {
    if (frame.identity) return perturbed_normal(normal, raw, p);
    const glm::dvec3 in = normalised(frame.in * raw);
    const glm::dvec3 out = normalised(frame.out * perturbed_normal(normal, in, p));
    return out == out ? out : raw;  // NaN from a degenerate transform: keep the surface's
}

}  // namespace lumen::render
