// POV-Ray 3.7's tilings 4, 6-9 and 11-24 as layouts (render/patterns/tiling_layout.hpp).
#pragma once
#include "render/patterns/tiling_layout.hpp"

namespace lumen::render {

// Tiling n's layout, or null where lumen has none (tilings 1, 2, 3, 5 and 10 are computed in
// render/patterns/tilings.cpp, 25-27, Penrose's, in render/patterns/penrose.cpp).
const TilingLayout* tiling_layout(int n);

}  // namespace lumen::render
