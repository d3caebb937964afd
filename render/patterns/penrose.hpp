// POV-Ray 3.7's Penrose tilings (tiling 25, 26, 27) in the x-z plane, measured against povray's
// 16-bit renders: see penrose.cpp for the constructions found.
#pragma once

namespace lumen::render {

// Tiling `type` (25 pentagons, 26 kites and darts, 27 rhombs) at (x, z): tile kind k of T kinds
// (6 for 25, 2 for 26 and 27) in [k/T, (k+1)/T], the flat middle at k/T rising with the bevel to
// (k+1)/T at the edges. Any other type gives 0. Deterministic, thread-safe, no allocation,
// O(log |(x, z)|) work; 0 beyond |(x, z)| = 1e30 and for NaN.
double penrose_tiles(int type, double x, double z);

}  // namespace lumen::render
