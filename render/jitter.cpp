#include "render/jitter.hpp"

#include <cstdint>
#include <utility>

namespace lumen::render {
namespace {

// H: a fixed permutation of 0..4095 built by POV-Ray's shuffle.
std::array<int, 4096> make_permutation() {
    std::array<int, 4096> h{};
    for (int i = 0; i < 4096; ++i) h[i] = i;
    int32_t r = 0;
    for (int i = 4095; i >= 0; --i) {
        r = int32_t(uint32_t(r) * 1812433253u + 12345u);
        const int j = ((r >> 16) & 0x7FFF) % 4096;
        std::swap(h[i], h[j]);
    }
    return h;
}

const std::array<int, 4096> kHash = make_permutation();

}  // namespace

int jitter_index(double x, double y, int mul_x, int mul_y) {
    // int() truncates toward zero; & on the two's-complement value (negative frame pixels).
    const int ix = int(x * mul_x), iy = int(y * mul_y);
    return kHash[(kHash[ix & 4095] ^ iy) & 4095] & 255;
}

int jitter_hash(int i) { return kHash[i & 4095]; }

void jitter2d(double x, double y, double& jx, double& jy) {
    const std::array<float, 256>& table = jitter_table();
    jx = table[jitter_index(x, y, 1021, 1019)];
    jy = table[jitter_index(x, y, 1019, 1021)];
}

}  // namespace lumen::render
