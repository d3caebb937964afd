// Noise (generators 1, 2 and 3) and DNoise, computed in POV-Ray's order of operations so that
// the results agree to the bit: the same lattice, corner order, weights and sums.
#include "noise/noise.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

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

// The lattice around a point: the xy hashes of the four columns, then a corner's record.
struct Lattice {
    Axis x, y, z;
    int hxy[2][2];
    explicit Lattice(const glm::dvec3& p) : x(axis(p.x)), y(axis(p.y)), z(axis(p.z)) {
        for (int a = 0; a < 2; ++a)
            for (int b = 0; b < 2; ++b) hxy[a][b] = kHash[kHash[x.i + a] ^ (y.i + b)];
    }
    int record(int a, int b, int c) const { return kHash[hxy[a][b] ^ (z.i + c)] & 255; }
    double weight(int a, int b, int c) const {
        return ((a ? x.s : x.t) * (b ? y.s : y.t)) * (c ? z.s : z.t);
    }
    // A record's value plus its gradient dotted with the offset from corner (a, b, c).
    double term(int k, int a, int b, int c) const {
        return 0.5 * kRTable[k] + kRTable[k + 1] * (x.f - a) + kRTable[k + 2] * (y.f - b) +
               kRTable[k + 3] * (z.f - c);
    }
};

// The raw lattice noise of generators 1 and 2, about [-1.05, 0.99].
double lattice_noise(const glm::dvec3& p) {
    const Lattice l(p);
    static constexpr int kCorners[8][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                                           {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
    double sum = 0;
    for (const auto& [a, b, c] : kCorners) sum += l.weight(a, b, c) * l.term(l.record(a, b, c), a, b, c);
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

glm::dvec3 dnoise(const glm::dvec3& p) {
    const Lattice l(p);
    static constexpr int kCorners[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                           {0, 1, 1}, {1, 1, 1}, {1, 0, 1}, {0, 0, 1}};
    glm::dvec3 r(0);
    for (const auto& [a, b, c] : kCorners) {
        const int h = l.record(a, b, c);
        const double w = l.weight(a, b, c);
        r.x += w * l.term(h, a, b, c);
        r.y += w * l.term(h + 4, a, b, c);
        r.z += w * l.term(h + 8, a, b, c);
    }
    return r;
}

}  // namespace lumen::noise
