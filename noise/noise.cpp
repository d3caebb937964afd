// Noise (generators 1, 2 and 3) and DNoise, computed in POV-Ray's order of operations so that
// the results agree to the bit: the same lattice, corner order, weights and sums.
#include "noise/noise.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "noise/tables.hpp"

namespace lumen::noise {
namespace {

using detail::kHash;
using detail::kRTable;

constexpr double kEpsilon = 1e-10;
// Beyond this a coordinate has no meaningful lattice cell (POV's int conversion overflows
// long before); keeping to it keeps the integer conversions defined. NaN goes to 0.
constexpr double kMaxCoordinate = 1e18;

double finite_coordinate(double c) {
    if (std::fabs(c) < kMaxCoordinate) return c;
    return std::isnan(c) ? 0.0 : std::copysign(kMaxCoordinate, c);
}

double smooth(double f) { return f * f * (3.0 - 2.0 * f); }

// One coordinate's lattice cell (mod 4096), fraction in the cell and the two corner weights.
struct Axis {
    int i;
    double f, s, t;  // fraction, weight of the upper corner, weight of the lower corner
};

Axis axis(double c) {
    c = finite_coordinate(c);
    // POV's floor, except within 1e-10 below an integer.
    const std::int64_t t = c >= 0 ? std::int64_t(c) : std::int64_t(c - (1.0 - kEpsilon));
    Axis a;
    a.i = int((t + 10000) & 4095);
    a.f = c - double(t);
    a.s = smooth(a.f);
    a.t = 1.0 - a.s;
    return a;
}

// The lattice around a point: the hashes of its eight corners, their weights and offsets.
// Corners are indexed a + 2b + 4c for the corner (a, b, c).
struct Lattice {
    int record[8];
    double weight[8];
    double dx[2], dy[2], dz[2];  // the offset from the lower (0) and upper (1) corner
    explicit Lattice(const glm::dvec3& p) {
        const Axis x = axis(p.x), y = axis(p.y), z = axis(p.z);
        dx[0] = x.f, dx[1] = x.f - 1;
        dy[0] = y.f, dy[1] = y.f - 1;
        dz[0] = z.f, dz[1] = z.f - 1;
        const double wx[2] = {x.t, x.s}, wy[2] = {y.t, y.s}, wz[2] = {z.t, z.s};
        for (int b = 0; b < 2; ++b)
            for (int a = 0; a < 2; ++a) {
                const int hxy = kHash[kHash[x.i + a] ^ (y.i + b)];
                const double wxy = wx[a] * wy[b];
                for (int c = 0; c < 2; ++c) {
                    const int k = a + 2 * b + 4 * c;
                    record[k] = kHash[hxy ^ (z.i + c)] & 255;
                    weight[k] = wxy * wz[c];
                }
            }
    }
    // Record r's value plus its gradient dotted with the offset from corner k.
    double term(int r, int k) const {
        return 0.5 * kRTable[r] + kRTable[r + 1] * dx[k & 1] + kRTable[r + 2] * dy[(k >> 1) & 1] +
               kRTable[r + 3] * dz[k >> 2];
    }
};

// DNoise's three records per hash, laid out for its loop: the x and y coefficients
// interleaved (value term halved, as POV stores it), then the z ones.
struct DNoiseRecord {
    alignas(16) double c[12];
};
constexpr std::array<DNoiseRecord, 256> kDNoiseRecords = [] {
    std::array<DNoiseRecord, 256> t{};
    for (int h = 0; h < 256; ++h) {
        for (int j = 0; j < 4; ++j) {
            const double half = j == 0 ? 0.5 : 1.0;
            t[h].c[2 * j] = half * kRTable[h + j];
            t[h].c[2 * j + 1] = half * kRTable[h + 4 + j];
            t[h].c[8 + j] = half * kRTable[h + 8 + j];
        }
    }
    return t;
}();

// Noise's record per hash: the value term (halved, as POV stores it) and the gradient.
struct NoiseRecord {
    alignas(32) double c[4];
};
constexpr std::array<NoiseRecord, 256> kNoiseRecords = [] {
    std::array<NoiseRecord, 256> t{};
    for (int h = 0; h < 256; ++h)
        for (int j = 0; j < 4; ++j) t[h].c[j] = (j == 0 ? 0.5 : 1.0) * kRTable[h + j];
    return t;
}();

// The raw lattice noise of generators 1 and 2, about [-1.05, 0.99]: the corners summed in
// POV's order, (000) (100) (010) (110) (001) (101) (011) (111). Corners a = 0 and a = 1 are
// computed side by side, lane by lane, and then added in that order.
double lattice_noise(const glm::dvec3& p) {
    const Lattice l(p);
    using Pair = double __attribute__((vector_size(16)));
    const Pair dx = {l.dx[0], l.dx[1]};
    double sum = 0;
    for (int k = 0; k < 8; k += 2) {
        const double* r0 = kNoiseRecords[l.record[k]].c;
        const double* r1 = kNoiseRecords[l.record[k + 1]].c;
        const double dy = l.dy[(k >> 1) & 1], dz = l.dz[k >> 2];
        const Pair c0 = {r0[0], r1[0]}, c1 = {r0[1], r1[1]}, c2 = {r0[2], r1[2]},
                   c3 = {r0[3], r1[3]};
        const Pair w = {l.weight[k], l.weight[k + 1]};
        const Pair t = w * (c0 + c1 * dx + c2 * dy + c3 * dz);
        sum += t[0];
        sum += t[1];
    }
    return sum;
}

double lerp(double t, double a, double b) { return a + t * (b - a); }

// Perlin's gradient noise (generator 3), on a lattice of period 2048 offset from the integers.
double solid_noise(const glm::dvec3& p) {
    const detail::SolidTables& st = detail::solid_tables();
    struct Coord {
        int b0, b1;
        double r0, r1;
    };
    auto coord = [](double c) {
        const double t = finite_coordinate(c) + 10000000.023157213;
        const double it = std::floor(t);
        Coord k;
        k.b0 = int(std::int64_t(it) & 2047);
        k.b1 = (k.b0 + 1) & 2047;
        k.r0 = t - it;
        k.r1 = k.r0 - 1.0;
        return k;
    };
    const Coord x = coord(p.x), y = coord(p.y), z = coord(p.z);
    const int i = st.perm[x.b0], j = st.perm[x.b1];
    const int b00 = st.perm[i + y.b0], b10 = st.perm[j + y.b0];
    const int b01 = st.perm[i + y.b1], b11 = st.perm[j + y.b1];
    auto g = [&](int k, double rx, double ry, double rz) {
        const glm::dvec3& v = st.grad[k];
        return v.x * rx + v.y * ry + v.z * rz;
    };
    const double sx = smooth(x.r0), sy = smooth(y.r0), sz = smooth(z.r0);
    auto layer = [&](int bz, double rz) {
        const double a = lerp(sx, g(b00 + bz, x.r0, y.r0, rz), g(b10 + bz, x.r1, y.r0, rz));
        const double b = lerp(sx, g(b01 + bz, x.r0, y.r1, rz), g(b11 + bz, x.r1, y.r1, rz));
        return lerp(sy, a, b);
    };
    const double raw = lerp(sz, layer(z.b0, z.r0), layer(z.b1, z.r1));
    return std::clamp(0.5 * (1.59 * raw + 0.985), 0.0, 1.0);
}

}  // namespace

double noise(const glm::dvec3& p, Generator generator) {
    switch (generator) {
        case Generator::Original: return std::clamp(lattice_noise(p) + 0.5, 0.0, 1.0);
        case Generator::Perlin: return solid_noise(p);
        case Generator::RangeCorrected: break;
    }
    // Spreads the raw range [-1.05242, 0.988997] over [0, 1].
    return std::clamp((lattice_noise(p) + 1.05242) * 0.48985582, 0.0, 1.0);
}

namespace {

using Pair = double __attribute__((vector_size(16)));
using Quad = double __attribute__((vector_size(32)));

// Whether the processor has AVX2 (asked once; a static initialiser may ask before libgcc's).
bool avx2() {
    static const bool has = (__builtin_cpu_init(), __builtin_cpu_supports("avx2"));
    return has;
}

// DNoise's records again, four lanes wide: per term (value, x, y and z gradient) the x, y and
// z coefficients and a zero, so that one 256-bit operation does what the pair and the scalar
// above do. The same operations on each lane, in the same order: the same bits.
struct DNoiseRecord4 {
    alignas(32) double c[16];
};
constexpr std::array<DNoiseRecord4, 256> kDNoiseRecords4 = [] {
    std::array<DNoiseRecord4, 256> t{};
    for (int h = 0; h < 256; ++h)
        for (int j = 0; j < 4; ++j) {
            t[h].c[4 * j] = kDNoiseRecords[h].c[2 * j];
            t[h].c[4 * j + 1] = kDNoiseRecords[h].c[2 * j + 1];
            t[h].c[4 * j + 2] = kDNoiseRecords[h].c[8 + j];
        }
    return t;
}();

// POV's corner order for DNoise: (000) (100) (110) (010) (011) (111) (101) (001).
constexpr int kDNoiseOrder[8] = {0, 1, 3, 2, 6, 7, 5, 4};

// The 256-bit form, for processors with AVX2 (chosen at run time; without them the pairs).
__attribute__((target("avx2"))) glm::dvec3 dnoise_wide(const glm::dvec3& p) {
    const Lattice l(p);
    Quad xyz = {0, 0, 0, 0};
    for (int k : kDNoiseOrder) {
        const double* c = kDNoiseRecords4[l.record[k]].c;
        const double dx = l.dx[k & 1], dy = l.dy[(k >> 1) & 1], dz = l.dz[k >> 2];
        Quad c0, c1, c2, c3;
        std::memcpy(&c0, c, sizeof c0);
        std::memcpy(&c1, c + 4, sizeof c1);
        std::memcpy(&c2, c + 8, sizeof c2);
        std::memcpy(&c3, c + 12, sizeof c3);
        xyz += l.weight[k] * (c0 + c1 * dx + c2 * dy + c3 * dz);
    }
    return {xyz[0], xyz[1], xyz[2]};
}

}  // namespace

glm::dvec3 detail::dnoise_in_pairs(const glm::dvec3& p) {
    const Lattice l(p);
    // x and y side by side in one register: the same operations, lane by lane.
    Pair xy = {0, 0};
    double z = 0;
    for (int k : kDNoiseOrder) {
        const double* c = kDNoiseRecords[l.record[k]].c;
        const double dx = l.dx[k & 1], dy = l.dy[(k >> 1) & 1], dz = l.dz[k >> 2];
        const double w = l.weight[k];
        Pair c0, c1, c2, c3;
        std::memcpy(&c0, c, sizeof c0);
        std::memcpy(&c1, c + 2, sizeof c1);
        std::memcpy(&c2, c + 4, sizeof c2);
        std::memcpy(&c3, c + 6, sizeof c3);
        xy += w * (c0 + c1 * dx + c2 * dy + c3 * dz);
        z += w * (c[8] + c[9] * dx + c[10] * dy + c[11] * dz);
    }
    return {xy[0], xy[1], z};
}

glm::dvec3 dnoise(const glm::dvec3& p) {
    return avx2() ? dnoise_wide(p) : detail::dnoise_in_pairs(p);
}

}  // namespace lumen::noise
