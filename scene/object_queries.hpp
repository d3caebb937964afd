// What the interpreter asks of the renderer about an object while a scene is being parsed:
// trace() and inside(). The renderer implements it (render/object_queries.cpp) and the caller
// hands it to the interpreter, so the interpreter needs no renderer to be built or tested.
#pragma once
#include <optional>

#include <glm/vec3.hpp>

#include "scene/object.hpp"

namespace lumen::scene {

class ObjectQueries {
public:
    virtual ~ObjectQueries() = default;
    struct Hit {
        glm::dvec3 point, normal;  // world space; the primitive's outward normal (inverse flips)
    };
    // The nearest surface of `object` along the ray from `origin` (dir unit length), if any.
    // Throws LumenError for a shape the renderer cannot intersect.
    virtual std::optional<Hit> trace(const ObjectPtr& object, const glm::dvec3& origin,
                                     const glm::dvec3& dir) = 0;
    // Whether `p` is inside `object` (surface points count as inside).
    virtual bool inside(const ObjectPtr& object, const glm::dvec3& p) = 0;
};

}  // namespace lumen::scene
