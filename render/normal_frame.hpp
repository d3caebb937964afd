// The space a texture_map entry's normal is perturbed in. POV evaluates a texture_map's entries
// at the map's pattern point, and turns their normals into the map's pattern space through
// its transforms (the transpose of each forward matrix, latest first) and back out after
// (the transpose of each inverse, in the order written), as render/normal.cpp does for a
// normal's own transforms. Nested maps compose; outside any map the frame is the identity.
#pragma once
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "scene/texture.hpp"

namespace lumen::render {

struct NormalFrame {
    glm::dmat3 in, out;  // world -> map space, map space -> world
    bool identity;

    static NormalFrame none() { return {glm::dmat3(1.0), glm::dmat3(1.0), true}; }
    // The frame of the texture_map pattern `pattern`.
    static NormalFrame of(const scene::Pattern& pattern);
    // This frame followed by `inner`, a map nested inside it.
    NormalFrame then(const NormalFrame& inner) const;
};

// `raw` perturbed by `normal` at point p (in the frame's space), through the frame: unit length.
glm::dvec3 framed_normal(const scene::Normal& normal, const glm::dvec3& raw,
                         const glm::dvec3& p, const NormalFrame& frame);

}  // namespace lumen::render
