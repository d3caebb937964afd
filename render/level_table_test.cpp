// The level table gives exactly the levels of the curve it was built from, everywhere.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <random>

#include "render/level_table.hpp"

namespace lumen::render {
namespace {

int quantise(float encoded) {
    return int(std::floor(std::clamp(double(encoded), 0.0, 1.0) * 255 + 0.5));
}
float srgb(float v) { return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1 / 2.4f) - 0.055f; }

void expect_same_levels(const std::function<int(float)>& level) {
    const LevelTable table(level);
    std::mt19937 rng(7);
    int checked = 0;
    auto check = [&](float v) {
        if (!(v > 0)) return;
        ASSERT_EQ(table(v), level(v)) << v;
        ++checked;
    };
    // Random bit patterns cover every magnitude; uniform values cover the visible range.
    std::uniform_int_distribution<uint32_t> bits(1, 0x7f800000);
    std::uniform_real_distribution<float> unit(0, 1.2f);
    for (int i = 0; i < 200000; ++i) {
        check(std::bit_cast<float>(bits(rng)));
        check(unit(rng));
    }
    // Both sides of every step, found by walking the floats near each level boundary.
    for (int k = 0; k < 255; ++k) {
        float lo = std::numeric_limits<float>::min(), hi = 4;
        while (std::nextafter(lo, hi) < hi) {  // bisect to the step up to level > k
            const float mid = lo + (hi - lo) / 2;
            if (mid <= lo || mid >= hi) break;
            (level(mid) > k ? hi : lo) = mid;
        }
        for (float v = lo, n = 0; n < 4; v = std::nextafter(v, 0.f), ++n) check(v);
        for (float v = hi, n = 0; n < 4; v = std::nextafter(v, 8.f), ++n) check(v);
    }
    for (float v : {std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::min(),
                    1.0f, 2.0f, std::numeric_limits<float>::max(),
                    std::numeric_limits<float>::infinity()})
        check(v);
    EXPECT_GT(checked, 400000);
}

TEST(LevelTable, SrgbCurve) { expect_same_levels([](float v) { return quantise(srgb(v)); }); }

TEST(LevelTable, LegacyBytesAreTheValues) {
    expect_same_levels([](float v) { return quantise(v); });
}

TEST(LevelTable, PowerLawsBothWays) {
    expect_same_levels([](float v) { return quantise(std::pow(v, 1 / 2.2f)); });
    expect_same_levels([](float v) { return quantise(srgb(std::pow(v, 2.2f))); });
}

}  // namespace
}  // namespace lumen::render
