// The 8-bit file level of a working value under the scene's transfer curve, looked up instead
// of computed: the curve's pow per channel was most of the cost of encoding an image.
#pragma once
#include <cstdint>
#include <functional>
#include <vector>

namespace lumen::render {

class LevelTable {
public:
    // `level` maps positive floats to 0..255, never falls as its argument rises, and gives 255
    // at +infinity. Builds in ~8000 calls of it (a bisection per level).
    explicit LevelTable(const std::function<int(float)>& level);
    // level(v) for v > 0 (+infinity included), in a few instructions.
    int operator()(float v) const;

private:
    static constexpr int kShift = 16;  // a bucket is 1/128 of a power of two
    float steps_[255];                 // steps_[k]: the least float at level k + 1 or above
    uint32_t first_bucket_ = 0;        // the bucket of steps_[0]
    std::vector<uint8_t> bucket_level_;  // level at the start of each bucket from there on
};

}  // namespace lumen::render
