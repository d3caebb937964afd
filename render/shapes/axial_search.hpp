// The ray set-up lathe and sor share: a unit direction (distances k = t·|d|), a slab ray for
// their boxes (padded against rounding), and the window [k_min, best] their search narrows.
#pragma once
#include <algorithm>
#include <optional>

#include <glm/geometric.hpp>

#include "render/bounds.hpp"
#include "render/shapes/shape.hpp"

namespace lumen::render {

inline Aabb padded_box(Aabb b) {
    const glm::dvec3 pad = 1e-9 * (glm::dvec3(1) + glm::abs(b.lo) + glm::abs(b.hi));
    return {b.lo - pad, b.hi + pad};
}

struct AxialSearch {
    glm::dvec3 P, D;
    double len, k_min, best;
    SlabRay slab;
    double t_min, t_max;  // the caller's range, in its ray's units
    // Whether distance k lies in the caller's range: k / len is what the caller gets, and k >
    // t_min len need not say that k / len > t_min (an ask from a hit got the same hit back).
    bool in_range(double k) const { return k / len > t_min && k / len < t_max; }
    // Empty when the ray has no direction or misses the padded box within [tmin, tmax].
    static std::optional<AxialSearch> start(const LocalRay& r, const Aabb& box, double tmin,
                                            double tmax) {
        const double len = glm::length(r.d);
        if (!(len > 0)) return std::nullopt;
        const glm::dvec3 D = r.d / len;
        const SlabRay slab(r.o, D);
        double enter, exit;
        if (!slab.hits(padded_box(box), tmin * len, tmax * len, enter, exit)) return std::nullopt;
        return AxialSearch{r.o, D, len, tmin * len,
                           std::min(tmax * len, exit * (1 + 1e-9) + 1e-9), slab, tmin, tmax};
    }
};

}  // namespace lumen::render
