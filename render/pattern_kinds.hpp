// The raw value of each rendered pattern kind at a point in pattern space (before frequency,
// phase and waves). render/pattern.cpp dispatches to these by overload: a kind the table
// marks rendered without its `evaluate` here does not compile.
#pragma once
#include <glm/vec3.hpp>

#include "scene/pattern_kinds.hpp"

namespace lumen::render {

double evaluate(const scene::pattern::Plain&, const glm::dvec3& p);
double evaluate(const scene::pattern::Checker&, const glm::dvec3& p);
double evaluate(const scene::pattern::Gradient& k, const glm::dvec3& p);
double evaluate(const scene::pattern::Planar&, const glm::dvec3& p);
double evaluate(const scene::pattern::Radial&, const glm::dvec3& p);
double evaluate(const scene::pattern::Onion&, const glm::dvec3& p);
double evaluate(const scene::pattern::Spherical&, const glm::dvec3& p);
double evaluate(const scene::pattern::Cylindrical&, const glm::dvec3& p);
double evaluate(const scene::pattern::Brick& k, const glm::dvec3& p);
double evaluate(const scene::pattern::Boxed&, const glm::dvec3& p);
double evaluate(const scene::pattern::Hexagon&, const glm::dvec3& p);
double evaluate(const scene::pattern::Square&, const glm::dvec3& p);
double evaluate(const scene::pattern::Triangular&, const glm::dvec3& p);

}  // namespace lumen::render
