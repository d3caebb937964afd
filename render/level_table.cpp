#include "render/level_table.hpp"

#include <bit>
#include <limits>

namespace lumen::render {

LevelTable::LevelTable(const std::function<int(float)>& level) {
    constexpr uint32_t kInf = 0x7f800000;  // the bits of +infinity: above every finite float
    for (int k = 1; k <= 255; ++k) {
        // The least positive float at level k or above, by bisection on the bit patterns
        // (ordered like the floats they encode); level(+0) is taken as 0.
        uint32_t below = k > 1 ? std::bit_cast<uint32_t>(steps_[k - 2]) - 1 : 0, at = kInf;
        while (at - below > 1) {
            const uint32_t mid = below + (at - below) / 2;
            (level(std::bit_cast<float>(mid)) >= k ? at : below) = mid;
        }
        steps_[k - 1] = std::bit_cast<float>(at);
    }
    first_bucket_ = std::bit_cast<uint32_t>(steps_[0]) >> kShift;
    const uint32_t last = std::bit_cast<uint32_t>(steps_[254]) >> kShift;
    bucket_level_.resize(last - first_bucket_ + 1);
    int k = 0;
    for (uint32_t b = first_bucket_; b <= last; ++b) {
        const float start = std::bit_cast<float>(b << kShift);
        while (k < 255 && steps_[k] <= start) ++k;
        bucket_level_[b - first_bucket_] = uint8_t(k);
    }
}

int LevelTable::operator()(float v) const {
    if (!(v >= steps_[0])) return 0;
    if (v >= steps_[254]) return 255;
    int k = bucket_level_[(std::bit_cast<uint32_t>(v) >> kShift) - first_bucket_];
    while (v >= steps_[k]) ++k;  // a step inside the bucket; stops below steps_[254]
    return k;
}

}  // namespace lumen::render
