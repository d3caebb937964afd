// The noise patterns' values against POV-Ray 3.7's (computed in double precision at one
// point), and how they take the pattern's settings: generator, classic turbulence, waves.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "noise/waveforms.hpp"
#include "render/pattern.hpp"
#include "render/patterns/noise_kinds.hpp"

namespace lumen::render {
namespace {

constexpr double kTol = 1e-13;
const glm::dvec3 kP(1.3, -2.7, 0.37);

scene::Pattern pattern_of(scene::PatternKind kind) {
    scene::Pattern p;
    p.kind = std::move(kind);
    return p;
}

template <class Kind> double value_at(const glm::dvec3& p, const scene::Pattern& pat) {
    return evaluate(std::get<Kind>(pat.kind), p, pat);
}

TEST(NoisePatterns, MatchPovAtAReferencePoint) {
    EXPECT_NEAR(value_at<pattern::Granite>(kP, pattern_of(pattern::Granite{})), 0.192765399992966,
                kTol);
    EXPECT_NEAR(value_at<pattern::Wrinkles>(kP, pattern_of(pattern::Wrinkles{})),
                0.741080549835352, kTol);
    EXPECT_NEAR(value_at<pattern::Crackle>(kP, pattern_of(pattern::Crackle{})), 0.398362597471043,
                kTol);
    EXPECT_NEAR(value_at<pattern::Cells>(kP, pattern_of(pattern::Cells{})), 0.299051815411076,
                kTol);
    EXPECT_EQ(value_at<pattern::Cells>(kP, pattern_of(pattern::Cells{})),
              noise::pattern_rand(noise::hash3d(1, -3, 0)));
    EXPECT_NEAR(value_at<pattern::Agate>(kP, pattern_of(pattern::Agate{})), 0.961940896833092,
                kTol);
}

TEST(NoisePatterns, BozoSpottedAndBumpsAreNoiseAndDentsItsCube) {
    const double n = noise::noise(kP, noise::Generator::RangeCorrected);
    EXPECT_EQ(value_at<pattern::Bozo>(kP, pattern_of(pattern::Bozo{})), n);
    EXPECT_EQ(value_at<pattern::Spotted>(kP, pattern_of(pattern::Spotted{})), n);
    EXPECT_EQ(value_at<pattern::Bumps>(kP, pattern_of(pattern::Bumps{})), n);
    EXPECT_EQ(value_at<pattern::Dents>(kP, pattern_of(pattern::Dents{})), n * n * n);
}

// The pattern's own generator wins; otherwise the scene's, through the shared globals.
TEST(NoisePatterns, GeneratorComesFromThePatternThenTheScene) {
    scene::Pattern p = pattern_of(pattern::Bozo{});
    auto globals = std::make_shared<scene::PatternGlobals>();
    globals->noise_generator = 3;
    p.globals = globals;
    EXPECT_EQ(value_at<pattern::Bozo>(kP, p), noise::noise(kP, noise::Generator::Perlin));
    p.noise_generator = 1;
    EXPECT_EQ(value_at<pattern::Bozo>(kP, p), noise::noise(kP, noise::Generator::Original));
}

TEST(NoisePatterns, MarbleAndSpiralsAddTheClassicTurbulenceAlongX) {
    scene::Pattern m = pattern_of(pattern::Marble{});
    EXPECT_EQ(value_at<pattern::Marble>(kP, m), kP.x);
    scene::TurbulenceParams& t = m.steps.classic_turbulence();
    t.amount = {0.5, 0.1, 0.1};
    t.octaves = 3;
    const double turb = noise::turbulence(kP, t, noise::Generator::RangeCorrected);
    EXPECT_EQ(value_at<pattern::Marble>(kP, m), kP.x + 0.5 * turb);
    // Marble's turbulence is inside its formula: the point is not also displaced.
    m.frequency = 0.25;
    m.wave = scene::WaveType::Ramp;
    EXPECT_NEAR(pattern_value(m, kP), std::fmod((kP.x + 0.5 * turb) * 0.25, 1.00001), 1e-15);
}

TEST(NoisePatterns, WoodRingsAroundZ) {
    scene::Pattern w = pattern_of(pattern::Wood{});
    EXPECT_EQ(value_at<pattern::Wood>(kP, w), std::sqrt(kP.x * kP.x + kP.y * kP.y));
    EXPECT_EQ(value_at<pattern::Wood>(kP + glm::dvec3(0, 0, 5), w), value_at<pattern::Wood>(kP, w));
    scene::TurbulenceParams& t = w.steps.classic_turbulence();
    t.amount = {0.2, 0.3, 0};
    const glm::dvec3 d = noise::dturbulence(kP, t);
    const double px = kP.x + noise::cycloidal((kP.x + d.x) * 0.2);
    const double py = kP.y + noise::cycloidal((kP.y + d.y) * 0.3);
    EXPECT_EQ(value_at<pattern::Wood>(kP, w), std::sqrt(px * px + py * py));
}

TEST(NoisePatterns, SpiralArmsWindAroundZ) {
    scene::Pattern s = pattern_of(pattern::Spiral1{{3}});
    // A quarter turn adds a quarter of the arms.
    const double a = value_at<pattern::Spiral1>({1, 0, 0}, s);
    const double b = value_at<pattern::Spiral1>({0, 1, 0}, s);
    EXPECT_NEAR(b - a, 3 * 0.25, 1e-12);
    EXPECT_EQ(value_at<pattern::Spiral1>({0, 0, 0.5}, s), 0.5);  // on the axis: height only
    scene::Pattern s2 = pattern_of(pattern::Spiral2{{3}});
    EXPECT_EQ(value_at<pattern::Spiral2>({0.25, 0, 0}, s2),
              noise::triangle_wave(0.25) + noise::triangle_wave(value_at<pattern::Spiral1>({0.25, 0, 0}, s)));
}

TEST(NoisePatterns, CrackleFormsMetricsAndSolid) {
    pattern::Crackle c;
    c.form = {1, 0, 0};
    const double d1 = value_at<pattern::Crackle>(kP, pattern_of(c));
    c.form = {0, 1, 0};
    const double d2 = value_at<pattern::Crackle>(kP, pattern_of(c));
    c.form = {-1, 1, 0};
    EXPECT_NEAR(value_at<pattern::Crackle>(kP, pattern_of(c)), d2 - d1, 1e-15);
    EXPECT_LE(d1, d2);
    c.form = {1, 0, 0};
    c.offset = 0.5;  // squared for metric 2, then the root
    EXPECT_NEAR(value_at<pattern::Crackle>(kP, pattern_of(c)), std::min(1.0, std::sqrt(d1 * d1 + 0.25)),
                1e-15);
    pattern::Crackle solid;
    solid.solid = true;
    // The noise at the nearest feature point is the same everywhere in its cell.
    EXPECT_EQ(value_at<pattern::Crackle>(kP, pattern_of(solid)),
              value_at<pattern::Crackle>(kP + glm::dvec3(1e-4, 0, 0), pattern_of(solid)));
    for (double metric : {1.0, 3.0, 0.5}) {
        pattern::Crackle m;
        m.metric = metric;
        const double v = value_at<pattern::Crackle>(kP, pattern_of(m));
        EXPECT_TRUE(v >= 0 && v <= 1) << metric;
    }
}

TEST(NoisePatterns, RipplesAndWavesUseTheScenesWaves) {
    scene::Pattern r = pattern_of(pattern::Ripples{});
    r.frequency = 2;
    r.phase = 0.25;
    auto globals = std::make_shared<scene::PatternGlobals>();
    globals->number_of_waves = 2;
    r.globals = globals;
    double sum = 0;
    for (const noise::Wave& w : noise::waves(2))
        sum += noise::cycloidal(glm::length(kP - w.source) * 2 + 0.25);
    EXPECT_NEAR(value_at<pattern::Ripples>(kP, r), 0.5 * (1 + sum / 2), 1e-15);
    scene::Pattern w = pattern_of(pattern::Waves{});
    w.globals = globals;
    double wsum = 0;
    for (const noise::Wave& wave : noise::waves(2))
        wsum += noise::cycloidal(glm::length(kP - wave.source) * wave.frequency) / wave.frequency;
    EXPECT_NEAR(value_at<pattern::Waves>(kP, w), 0.2 * (2.5 + wsum / 2), 1e-15);
}

// Classic turbulence displaces in the pattern's own (scaled) space; a warp turbulence where it
// is written among the transforms.
TEST(NoisePatterns, TurbulenceStepsDisplaceThePoint) {
    scene::Pattern p = pattern_of(pattern::Bozo{});
    const scene::Transform scale{glm::scale(glm::dmat4(1.0), glm::dvec3(0.5)),
                                 glm::scale(glm::dmat4(1.0), glm::dvec3(2.0))};
    p.steps.add_transform(scale);
    p.steps.classic_turbulence().amount = glm::dvec3(0.4);
    const glm::dvec3 tp = kP * 2.0;
    const glm::dvec3 displaced = tp + noise::dturbulence(tp, scene::TurbulenceParams{}) * 0.4;
    EXPECT_EQ(pattern_value(p, kP), noise::noise(displaced, noise::Generator::RangeCorrected));
    // `scale 0.5 warp { turbulence 0.4 }`: the world point is displaced, then scaled.
    scene::warp::Turbulence warp;
    warp.amount = glm::dvec3(0.4);
    scene::Pattern w = pattern_of(pattern::Bozo{});
    w.steps.add_transform(scale);
    w.steps.steps.push_back(warp);
    const glm::dvec3 moved = (kP + noise::dturbulence(kP, warp) * 0.4) * 2.0;
    EXPECT_EQ(pattern_value(w, kP), noise::noise(moved, noise::Generator::RangeCorrected));
    // `warp { turbulence 0.4 } scale 0.5`: scaled, then displaced, like the classic one.
    scene::Pattern v = pattern_of(pattern::Bozo{});
    v.steps.steps.push_back(warp);
    v.steps.add_transform(scale);
    EXPECT_EQ(pattern_value(v, kP), pattern_value(p, kP));
}

TEST(NoisePatterns, FrequencyZeroSkipsTheWaveStep) {
    scene::Pattern p = pattern_of(pattern::Marble{});
    p.wave = scene::WaveType::Triangle;
    p.frequency = 0;
    p.phase = 0.3;
    EXPECT_EQ(pattern_value(p, {0.75, 0, 0}), 0.5);  // triangle(0.75), no phase added
}

}  // namespace
}  // namespace lumen::render
