// POV-Ray 3.7's noise values: the tables' check values and the noise, dnoise and turbulence
// at reference points, as computed by POV-Ray (double precision).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "noise/noise.hpp"
#include "noise/tables.hpp"
#include "noise/waveforms.hpp"

namespace lumen::noise {
namespace {

constexpr double kTol = 1e-13;

TEST(NoiseTables, HashIsPovsShuffle) {
    const int expected[12] = {2291, 2574, 3654, 1557, 1196, 3388, 2637, 1820, 2436, 762, 2037, 3527};
    for (int i = 0; i < 12; ++i) EXPECT_EQ(detail::kHash[i], expected[i]) << i;
    for (int i = 0; i < detail::kHashSize; ++i)
        ASSERT_EQ(detail::kHash[i + detail::kHashSize], detail::kHash[i]);
    EXPECT_EQ(hash3d(1, -3, 0), 513);
    EXPECT_EQ(hash3d(1 + 4096, -3 - 4096, 8192), 513);  // period 4096 per axis
}

TEST(NoiseTables, SolidNoiseTables) {
    const detail::SolidTables& t = detail::solid_tables();
    const int perm[12] = {0, 1, 386, 3, 649, 1576, 1405, 7, 1146, 9, 1663, 11};
    for (int i = 0; i < 12; ++i) EXPECT_EQ(t.perm[i], perm[i]) << i;
    EXPECT_NEAR(t.grad[0].x, 0.6044250694, 1e-10);
    EXPECT_NEAR(t.grad[0].y, 0.7052602895, 1e-10);
    EXPECT_NEAR(t.grad[0].z, 0.3705108088, 1e-10);
    EXPECT_EQ(t.perm[4096], t.perm[0]);
    EXPECT_EQ(t.perm[4097], t.perm[1]);
}

TEST(NoiseTables, PatternRandsAreMt19937) {
    const double expected[4] = {0.8147236919, 0.1354770041, 0.9057919341, 0.8350085898};
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(pattern_rand(i), expected[i], 1e-10) << i;
    EXPECT_EQ(pattern_rand(32768 + 2), pattern_rand(2));
}

TEST(NoiseTables, WaveSourcesAndFrequencies) {
    const double src[10][3] = {{-0.604378, 0.492048, -0.626590}, {-0.552573, -0.246075, -0.796310},
                               {-0.444551, 0.623329, 0.643300},  {0.496586, 0.668948, 0.553092},
                               {-0.064372, -0.805952, -0.588471}, {0.246190, -0.914557, -0.320899},
                               {-0.666089, -0.591879, -0.453878}, {-0.520489, -0.386027, -0.761626},
                               {0.137949, -0.704642, -0.696024},  {0.564897, 0.722041, -0.399436}};
    const double freq[10] = {0.919115879, 0.960041200, 0.433169652, 0.709301126, 0.689189428,
                             0.991444746, 0.782972808, 0.400667440, 0.229672231, 0.168513138};
    const auto w = waves(10);
    ASSERT_EQ(w.size(), 10u);
    for (int i = 0; i < 10; ++i) {
        EXPECT_NEAR(w[i].source.x, src[i][0], 1e-6) << i;
        EXPECT_NEAR(w[i].source.y, src[i][1], 1e-6) << i;
        EXPECT_NEAR(w[i].source.z, src[i][2], 1e-6) << i;
        EXPECT_NEAR(w[i].frequency, freq[i], 1e-9) << i;
    }
    EXPECT_EQ(waves(0).size(), 1u);   // POV makes at least one wave
    EXPECT_EQ(waves(-3).size(), 1u);
    EXPECT_EQ(waves(3)[2].frequency, w[2].frequency);  // the count does not change a wave
}

struct Reference {
    glm::dvec3 p;
    double gen1, gen2, gen3;
    glm::dvec3 d;
};
const Reference kReferences[] = {
    {{0.5, 0.5, 0.5}, 0.41346047125, 0.473142170266155, 0.672103843552658,
     {-0.08653952875, -0.19951749375, 0.07361524375}},
    {{1.3, -2.7, 0.37}, 0.962106769680104, 0.741899752673599, 0.675620163637665,
     {0.462106769680104, -0.073638712776967, -0.210533608108356}},
    {{-0.25, 10.6, -3.3}, 0.3226876663558, 0.428676583491007, 0.561732925546961,
     {-0.1773123336442, 0.0494528618595799, 0.0653292985416842}},
};

TEST(Noise, MatchesPovAtReferencePoints) {
    for (const Reference& r : kReferences) {
        EXPECT_NEAR(noise(r.p, Generator::Original), r.gen1, kTol);
        EXPECT_NEAR(noise(r.p, Generator::RangeCorrected), r.gen2, kTol);
        EXPECT_NEAR(noise(r.p, Generator::Perlin), r.gen3, kTol);
        const glm::dvec3 d = dnoise(r.p);
        EXPECT_NEAR(d.x, r.d.x, kTol);
        EXPECT_NEAR(d.y, r.d.y, kTol);
        EXPECT_NEAR(d.z, r.d.z, kTol);
        // DNoise's x is the unclamped generator-1 sum.
        EXPECT_NEAR(d.x + 0.5, r.gen1, kTol);
    }
}

// POV's lattice noise written out term by term as POV orders it, to check the optimised
// implementation bit for bit.
struct Literal {
    int ix, iy, iz;
    double fx, fy, fz, sx, sy, sz, tx, ty, tz;
    explicit Literal(const glm::dvec3& p) {
        auto setup = [](double c, int& i, double& f, double& s, double& t) {
            const int n = c >= 0 ? int(c) : int(c - (1 - 1e-10));
            i = (n + 10000) & 4095;
            f = c - n;
            s = f * f * (3 - 2 * f);
            t = 1 - s;
        };
        setup(p.x, ix, fx, sx, tx);
        setup(p.y, iy, fy, sy, ty);
        setup(p.z, iz, fz, sz, tz);
    }
    double corner(int a, int b, int c, int offset, double& weight) const {
        const auto& H = detail::kHash;
        const int h = (H[H[H[ix + a] ^ (iy + b)] ^ (iz + c)] & 255) + offset;
        const double* v = detail::kRTable;
        weight = ((a ? sx : tx) * (b ? sy : ty)) * (c ? sz : tz);
        return 0.5 * v[h] + v[h + 1] * (fx - a) + v[h + 2] * (fy - b) + v[h + 3] * (fz - c);
    }
};

TEST(Noise, OptimisedLoopsAreBitForBitPovsSums) {
    const int noise_order[8][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                                   {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
    const int dnoise_order[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                    {0, 1, 1}, {1, 1, 1}, {1, 0, 1}, {0, 0, 1}};
    for (int i = 0; i < 5000; ++i) {
        const glm::dvec3 p(std::sin(i * 0.7) * 40, i * 0.013 - 30, std::cos(i * 1.3) * 7);
        const Literal l(p);
        double sum = 0, w;
        for (const auto& c : noise_order) {
            const double t = l.corner(c[0], c[1], c[2], 0, w);
            sum += w * t;
        }
        ASSERT_EQ(noise(p, Generator::Original), std::clamp(sum + 0.5, 0.0, 1.0)) << i;
        ASSERT_EQ(noise(p, Generator::RangeCorrected),
                  std::clamp((sum + 1.05242) * 0.48985582, 0.0, 1.0))
            << i;
        glm::dvec3 d(0);
        for (const auto& c : dnoise_order) {
            const double tx = l.corner(c[0], c[1], c[2], 0, w);
            d.x += w * tx;
            d.y += w * l.corner(c[0], c[1], c[2], 4, w);
            d.z += w * l.corner(c[0], c[1], c[2], 8, w);
        }
        ASSERT_EQ(dnoise(p), d) << i;
        ASSERT_EQ(detail::dnoise_in_pairs(p), d) << i;
    }
}

TEST(Noise, StaysInRangeAndRepeatsEvery4096Cells) {
    for (int i = 0; i < 2000; ++i) {
        const glm::dvec3 p(i * 0.37 - 300, i * 1.13 - 900, std::sin(i) * 50);
        for (Generator g : {Generator::Original, Generator::RangeCorrected, Generator::Perlin}) {
            const double n = noise(p, g);
            ASSERT_GE(n, 0.0);
            ASSERT_LE(n, 1.0);
        }
        ASSERT_NEAR(noise(p, Generator::RangeCorrected),
                    noise(p + glm::dvec3(4096, -8192, 0), Generator::RangeCorrected), 1e-9)
            << i;
    }
}

TEST(Noise, HugeAndNonFiniteCoordinatesAreDefined) {
    const double inf = std::numeric_limits<double>::infinity();
    for (double c : {1e30, -1e30, inf, -inf, std::numeric_limits<double>::quiet_NaN()}) {
        const glm::dvec3 p(c, 0.5, c);
        for (Generator g : {Generator::Original, Generator::RangeCorrected, Generator::Perlin}) {
            const double n = noise(p, g);
            EXPECT_TRUE(n >= 0 && n <= 1) << c;
        }
        const glm::dvec3 d = dnoise(p);
        EXPECT_TRUE(std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z)) << c;
    }
}

TEST(Turbulence, MatchesPovWithDefaultParameters) {
    const scene::TurbulenceParams params;  // 6 octaves, omega 0.5, lambda 2
    const glm::dvec3 p(1.3, -2.7, 0.37);
    EXPECT_NEAR(turbulence(p, params, Generator::Original), 1.42010207122095, kTol);
    EXPECT_NEAR(turbulence(p, params, Generator::RangeCorrected), 1.4724272529956, kTol);
    EXPECT_NEAR(turbulence(p, params, Generator::Perlin), 1.27868834003106, kTol);
    const glm::dvec3 d = dturbulence(p, params);
    EXPECT_NEAR(d.x, 0.435727071220954, kTol);
    EXPECT_NEAR(d.y, -0.00625573178864871, kTol);
    EXPECT_NEAR(d.z, -0.177349942285049, kTol);
}

TEST(Turbulence, OctavesScaleFrequencyAndAmplitude) {
    const glm::dvec3 p(0.3, 1.7, -2.2);
    scene::TurbulenceParams one;
    one.octaves = 1;
    EXPECT_EQ(dturbulence(p, one), dnoise(p));
    EXPECT_EQ(turbulence(p, one, Generator::Original), noise(p, Generator::Original));
    scene::TurbulenceParams two = one;
    two.octaves = 2;
    two.lambda = 3;
    two.omega = 0.25;
    const glm::dvec3 expected = dnoise(p) + 0.25 * dnoise(p * 3.0);
    EXPECT_NEAR(dturbulence(p, two).y, expected.y, 1e-15);
    // Generator 2 clamps the first octave only.
    const double first = std::clamp(2 * noise(p, Generator::RangeCorrected) - 0.5, 0.0, 1.0);
    EXPECT_NEAR(turbulence(p, two, Generator::RangeCorrected),
                first + 0.25 * (2 * noise(p * 3.0, Generator::RangeCorrected) - 0.5), 1e-15);
    // Octaves are clamped to 1..10.
    scene::TurbulenceParams many;
    many.octaves = 50;
    scene::TurbulenceParams ten;
    ten.octaves = 10;
    EXPECT_EQ(dturbulence(p, many), dturbulence(p, ten));
    scene::TurbulenceParams none;
    none.octaves = -4;
    EXPECT_EQ(dturbulence(p, none), dnoise(p));
}

TEST(Waveforms, CycloidalAndTriangle) {
    for (double v : {0.0, 0.1, 0.25, 0.7, 3.3, -0.25, -2.6}) {
        EXPECT_NEAR(cycloidal(v), std::sin(2 * std::numbers::pi * v), 1e-12) << v;
        EXPECT_EQ(cycloidal(-v), -cycloidal(v)) << v;
    }
    EXPECT_EQ(triangle_wave(0.25), 0.5);
    EXPECT_EQ(triangle_wave(0.5), 1.0);
    EXPECT_EQ(triangle_wave(0.75), 0.5);
    EXPECT_EQ(triangle_wave(2.0), 0.0);
    EXPECT_EQ(triangle_wave(-0.25), 0.5);
    EXPECT_NEAR(triangle_wave(-1.4), 0.8, 1e-12);  // o = 0.6
}

TEST(Generator, PatternsOwnChoiceOverridesTheScene) {
    EXPECT_EQ(resolve_generator(0, 1), Generator::Original);
    EXPECT_EQ(resolve_generator(3, 1), Generator::Perlin);
    EXPECT_EQ(resolve_generator(0, 2), Generator::RangeCorrected);
    EXPECT_EQ(resolve_generator(0, 7), Generator::RangeCorrected);
}

}  // namespace
}  // namespace lumen::noise
