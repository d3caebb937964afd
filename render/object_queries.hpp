// The renderer's answers to the interpreter's trace() and inside() (scene/object_queries.hpp).
#pragma once
#include <memory>

#include "scene/object_queries.hpp"

namespace lumen::render {

// Geometry is compiled once per object and kept for later calls (loops trace one object
// thousands of times). Not thread-safe: one interpreter uses it at a time.
std::shared_ptr<scene::ObjectQueries> make_object_queries();

}  // namespace lumen::render
