// The tables built at first use: Perlin's gradients and permutation, PatternRands and the
// wave sources. The hash table and RTable are compile-time constants (noise/tables.hpp).
#include <cmath>
#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "noise/noise.hpp"
#include "noise/tables.hpp"

namespace lumen::noise {
namespace detail {

const SolidTables& solid_tables() {
    static const SolidTables tables = [] {
        SolidTables t;
        Lcg lcg{1};  // one sequence feeds the gradients, then the permutation
        auto component = [&] { return double(lcg.next() % 4096 - 2048) / 2048; };
        for (int i = 0; i < kSolidEntries; ++i) {
            glm::dvec3 g;
            double len2;
            do {
                g.x = component();
                g.y = component();
                g.z = component();
                len2 = g.x * g.x + g.y * g.y + g.z * g.z;
            } while (len2 < 1e-5 || len2 > 1);
            t.grad[i] = g * (1 / std::sqrt(len2));
        }
        for (int i = 0; i < kSolidEntries; ++i) t.perm[i] = i;
        // POV shuffles the even slots only, from slot 2048 (left 0) down: 0 can occur twice.
        for (int i = kSolidEntries; i > 0; i -= 2) {
            const int k = t.perm[i];
            const int j = lcg.next() % kSolidEntries;
            t.perm[i] = t.perm[j];
            t.perm[j] = k;
        }
        // In increasing order, so the last two slots get the already copied slots 0 and 1.
        for (int i = 0; i < kSolidEntries + 2; ++i) {
            t.perm[kSolidEntries + i] = t.perm[i];
            t.grad[kSolidEntries + i] = t.grad[i];
        }
        return t;
    }();
    return tables;
}

const std::array<double, kPatternRands>& pattern_rands() {
    static const std::array<double, kPatternRands> rands = [] {
        std::array<double, kPatternRands> r;
        std::mt19937 mt;  // default seed 5489, as boost's
        for (double& v : r) v = double(mt()) / 4294967296.0;
        return r;
    }();
    return rands;
}

}  // namespace detail

int hash3d(int a, int b, int c) {
    using detail::kHash;
    return kHash[kHash[kHash[a & 4095] ^ (b & 4095)] ^ (c & 4095)];
}

double pattern_rand(int i) { return detail::pattern_rands()[i & (detail::kPatternRands - 1)]; }

std::span<const Wave> waves(int count) {
    static const std::vector<Wave> table = [] {
        std::vector<Wave> w(kMaxWaves);
        detail::Lcg lcg{std::uint32_t(-560851967)};
        for (int i = 0; i < kMaxWaves; ++i) {
            const glm::dvec3 d = dnoise({double(i), 0, 0});
            const double len = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
            w[i].source = len > 0 ? d / len : d;
            w[i].frequency = lcg.next() * 0.000030518509476 + 0.01;
        }
        return w;
    }();
    const int n = count < 1 ? 1 : count > kMaxWaves ? kMaxWaves : count;
    return {table.data(), std::size_t(n)};
}

}  // namespace lumen::noise
