// A box around a bounded poly surface. POV-Ray tests every ray against a poly (its box is
// infinite); a polynomial whose top-degree part is positive on the unit sphere has all of
// F(p) <= kPolyInside within a sphere whose radius follows from rigorous bounds of each
// degree's part on the unit sphere, so rays that miss that box can skip the solver (the
// roots of rays that reach it are unchanged).
#pragma once
#include <vector>

#include "render/bounds.hpp"

namespace lumen::render {

struct PolyTerm {
    double c;
    int i, j, k;
};

// The cube [-R, R]^3 outside of which F(p) > `inside_level` everywhere, or everything when
// no such R is proved (odd or indefinite top degree, overflow).
Aabb poly_bound_box(const std::vector<PolyTerm>& terms, double inside_level);

}  // namespace lumen::render
