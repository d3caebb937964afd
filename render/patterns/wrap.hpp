// POV-Ray's wrap of a coordinate into [0, n): fmod with the sign fixed, and a rounding result
// of exactly n sent to 0 (tilings, image maps).
#pragma once
#include <cmath>

namespace lumen::render {

inline double wrap(double v, double n) {
    double t = std::fmod(v, n);
    if (t < 0) t += n;
    if (t >= n) t = 0;
    return t;
}

}  // namespace lumen::render
