// Checks of the scene's radiosity mesh that are reported, not fixed (issue 4, stability):
// sliver elements and coincident surfaces. Edge-sharing elements need no report: the mesh
// welds their shared vertices, so values interpolate across the edge.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "render/radiosity/scene_mesh.hpp"

namespace lumen::render::radiosity {

// An element is a sliver when its longest edge² exceeds this many times its area (its height
// is below about 1/500 of its length): its gathers start from a point that is nearly on an
// edge, and its vertex values carry almost no area.
inline constexpr double kSliverRatio = 1000;

// Appends one warning, with the object's source location, per object that has sliver
// elements, and one per pair of objects whose surfaces coincide: coplanar, overlapping and
// facing the same way (z-fighting; each point then belongs to whichever a ray happens to hit
// first). Surfaces in contact, facing each other (a box resting on a floor), are not reported,
// nor coincident surfaces where `hidden(p, n)` says no ray reaches point p from the side of
// its normal n (both face into opaque matter: the bottoms of a column and of the slab it
// stands in, on the ground plane).
using HiddenSide = std::function<bool(const glm::dvec3& p, const glm::dvec3& n)>;
void report_mesh_problems(const SceneMesh& mesh, std::vector<std::string>& warnings,
                          const HiddenSide& hidden = {});

}  // namespace lumen::render::radiosity
