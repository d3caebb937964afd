// A feature that parses but that lumen does not implement. It travels as a value and only
// becomes an error if it reaches the rendered scene (tolerant loading).
#pragma once
#include <string>

#include "base/source.hpp"

namespace lumen::scene {

struct Unsupported {
    std::string feature;  // e.g. "isosurface", "pattern 'bozo'", "normal { bumps }"
    SourceLoc loc;
};

}  // namespace lumen::scene
