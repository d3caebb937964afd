// rainbow { } against values POV-Ray 3.7 rendered (16-bit linear PNGs, File_Gamma 1, one
// ray per pixel of a 101 x 101 image with a 90-degree camera along +z).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "render/rainbow.hpp"

namespace lumen::render {
namespace {

scene::Rainbow ring(scene::Colour c, double distance = 1e7) {
    scene::Rainbow r;
    r.angle = 20;
    r.width = 10;
    r.distance = distance;
    r.colour_map = {{0, c}, {1, c}};
    return r;
}

// The camera ray through pixel column x of the middle row.
glm::dvec3 ray_of(int x) { return glm::normalize(glm::dvec3((x + 0.5 - 50.5) / 50.5, 0, 1)); }

// One rainbow over `behind`, with the jitter placed at u.
glm::dvec3 through_rainbow(const scene::Rainbow& r, const glm::dvec3& dir, double depth,
                           const glm::dvec3& behind, double u, double& transmit) {
    return through_rainbows({r}, dir, depth, behind, [u] { return u; }, transmit);
}

void expect_rgb(const glm::dvec3& got, const glm::dvec3& want) {
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], want[i], 2e-5) << "channel " << i;
}

constexpr double kSky = 2e10;  // POV-Ray's depth of a ray that hits nothing
const glm::dvec3 kBackground(0.5, 0.6, 0.7);

TEST(Rainbow, TheBandTakesTheMapAcrossIt) {
    scene::Rainbow r = ring({});
    r.colour_map = {{0, {0, 0, 0}}, {1, {1, 1, 1}}};
    double t = 1;
    // 17.58 degrees off the direction: 0.258 of the way across 15..25 degrees.
    expect_rgb(through_rainbow(r, ray_of(66), kSky, kBackground, 0, t), glm::dvec3(0.2580));
    EXPECT_EQ(t, 0);
    t = 1;
    expect_rgb(through_rainbow(r, ray_of(60), kSky, kBackground, 0, t), kBackground);  // 11.2 degrees
    EXPECT_EQ(t, 1);
    r.direction = {0, 0, -1};  // the ring behind the camera
    expect_rgb(through_rainbow(r, ray_of(66), kSky, kBackground, 0, t), kBackground);
}

TEST(Rainbow, FilterAndTransmitOverTheSky) {
    double t = 1;
    expect_rgb(through_rainbow(ring({0.8, 0.4, 0.2, 0, 0.2}), ray_of(68), kSky, kBackground, 0, t),
               {0.74, 0.43999, 0.30001});
    expect_rgb(through_rainbow(ring({0.8, 0.4, 0.2, 0.5, 0.2}), ray_of(68), kSky, kBackground, 0, t),
               {0.73201, 0.41120, 0.25521});
    expect_rgb(through_rainbow(ring({0.8, 0.4, 0.2, 1, 0}), ray_of(68), kSky, kBackground, 0, t),
               {0.8, 0.4, 0.2});
}

TEST(Rainbow, DistanceActsAsAFogsOverObjectsAndTheSky) {
    double t = 1;
    // A wall at z = 30 (grey 0.3), distance 50: the rainbow covers 1 - e^(-depth/50) of it.
    const glm::dvec3 d = ray_of(30);
    expect_rgb(through_rainbow(ring({0.8, 0.4, 0.2, 0.5, 0.2}, 50), d, 30 / d.z, glm::dvec3(0.3), 0, t),
               {0.53028, 0.32511, 0.22252});
    // The sky at distance 2e10: e^-1 shows through.
    expect_rgb(through_rainbow(ring({0.8, 0.4, 0.2}, 2e10), ray_of(68), kSky, kBackground, 0, t),
               {0.68963, 0.47358, 0.38393});
}

TEST(Rainbow, JitterMovesThePositionBeforeTheBandsEndsAreTested) {
    scene::Rainbow r = ring({});
    r.colour_map = {{0, {0, 0, 0}}, {1, {1, 1, 1}}};
    r.jitter = 0.5;
    double t = 1;
    // 0.163 before the band: u = 1 moves it 0.5 into it; u = 0.5 leaves it outside.
    EXPECT_NEAR(through_rainbow(r, ray_of(62), kSky, kBackground, 1, t).x, 0.5 - 0.1633, 1e-3);
    expect_rgb(through_rainbow(r, ray_of(62), kSky, kBackground, 0.5, t), kBackground);
}

TEST(Rainbow, OddSettingsGiveNoNaN) {
    for (double distance : {0.0, -5.0, 1e-300}) {
        double t = 1;
        const glm::dvec3 c = through_rainbow(ring({0.8, 0.4, 0.2, 0.5, 0.2}, distance), ray_of(68), 10,
                                             kBackground, 0, t);
        EXPECT_TRUE(std::isfinite(c.x + c.y + c.z + t)) << distance;
        EXPECT_LE(c.x, 1.0);
    }
    scene::Rainbow r = ring({1, 1, 1});
    r.direction = glm::dvec3(0);
    double t = 1;
    expect_rgb(through_rainbow(r, ray_of(68), kSky, kBackground, 0, t), kBackground);
}

// tests/atmosphere/rainbow.pov's two bands, pixel (90, 108) over the sky: 0.783 across the
// first band and just inside the second's clear edge. POV-Ray averages the two results.
TEST(Rainbow, OverlappingBandsAverage) {
    scene::Rainbow a;
    a.angle = 30;
    a.width = 8;
    a.direction = {0.1, -0.3, 1};
    a.colour_map = {{0, {0.6, 0.2, 1, 1, 0}}, {0.2, {0.2, 0.3, 1, 0.6, 0}},
                    {0.5, {0.2, 1, 0.3, 0.4, 0.2}}, {0.8, {1, 0.9, 0.2, 0.5, 0}},
                    {1, {1, 0.2, 0.1, 0, 1}}};
    scene::Rainbow b;
    b.angle = 12;
    b.width = 6;
    b.distance = 40;
    b.direction = {-0.2, 0.1, 1};
    b.colour_map = {{0, {1, 1, 1, 0, 1}}, {0.5, {1, 0.5, 0.2, 0, 0.3}}, {1, {1, 1, 1, 0, 1}}};
    // POV-Ray's default camera: right 1.33, up 1, angle 80 sets the direction's length.
    const double z = 0.5 * 1.33 / std::tan(40 * std::acos(-1.0) / 180);
    const glm::dvec3 d = glm::normalize(glm::dvec3(((90 + 0.5) / 320 - 0.5) * 1.33, 0.5 - 108.5 / 240, z));
    double t = 1;
    expect_rgb(through_rainbows({a, b}, d, kSky, {0.45, 0.6, 0.85}, [] { return 0.0; }, t),
               {0.700435, 0.750973, 0.529473});
}

// A partial arc (POV-Ray's profile, probed): full within falloff_angle/2 of up's azimuth,
// 1 - 3x^2 + 2x^3 across the fade, nothing past arc_angle/2; the azimuth is taken around the
// rainbow's axis, so up's component along it does not matter.
TEST(Rainbow, ArcStrengthFadesSmoothlyToTheArcsEnds) {
    const scene::Rainbow::Arc arc{180, 60};  // full to 30 degrees, gone past 90
    const glm::dvec3 axis(0, 0, 1), up(0, 1, 0);
    auto at = [&](double azimuth_deg) {
        const double a = azimuth_deg * std::numbers::pi / 180;
        return arc_strength(arc, axis, up, glm::normalize(glm::dvec3(std::sin(a), std::cos(a), 2)));
    };
    EXPECT_DOUBLE_EQ(at(0), 1);
    EXPECT_DOUBLE_EQ(at(29), 1);
    EXPECT_NEAR(at(60), 0.5, 1e-9);
    EXPECT_NEAR(at(-45), 1 - 3 * 0.0625 + 2 * 0.015625, 1e-9);  // x = 1/4, either side
    EXPECT_DOUBLE_EQ(at(91), 0);
    const glm::dvec3 tilted_up(0, 1, 5), straight_up = glm::normalize(glm::dvec3(0, 1, 2));
    EXPECT_DOUBLE_EQ(arc_strength(arc, axis, tilted_up, straight_up), 1);
}

}  // namespace
}  // namespace lumen::render
