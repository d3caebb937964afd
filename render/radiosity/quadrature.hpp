// Gauss-Legendre rules on [0, 1], optionally composite with cells graded toward both ends.
#pragma once
#include <utility>
#include <vector>

namespace lumen::render::radiosity {

// (node, weight) pairs on [0, 1]; the weights sum to 1.
using Rule = std::vector<std::pair<double, double>>;

// `order`-point Gauss-Legendre on [0, 1] (order clamped to 1..64).
Rule gauss_legendre(int order);

// Composite rule: cells with breakpoints 0, 2^-(2g+1), ..., 1/8, 1/2, 7/8, ..., 1,
// `order` points each. Cached; the reference stays valid for the program's lifetime.
const Rule& graded_rule(int order, int grading);

}  // namespace lumen::render::radiosity
