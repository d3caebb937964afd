// Fog along a segment, against values read from POV-Ray 3.7 renders: a white plane lit by a
// light 10 units above it through fog of distance 10, seen from 0.001 units away, with the
// light's media_attenuation on and off (16-bit linear output).
#include <gtest/gtest.h>

#include <cmath>

#include "render/fog.hpp"

namespace lumen::render {
namespace {

scene::Fog fog(scene::Colour c) {
    scene::Fog f;
    f.distance = 10;
    f.colour = c;
    return f;
}

const Ray kUp{{0, 0, 0}, {0, 1, 0}};
constexpr noise::Generator kGen = noise::Generator::RangeCorrected;

TEST(Fog, ConstantFogLetsThroughExpOfMinusDepthOverDistance) {
    const FogEffect e = fog_along({fog({0, 0, 0, 0, 0})}, kUp, 10, kGen);
    EXPECT_NEAR(e.attenuation.x, 0.367849, 1e-4);  // POV: 0.367849 with media_attenuation on
    EXPECT_NEAR(e.transmit, std::exp(-1.0), 1e-12);
    EXPECT_EQ(e.added, glm::dvec3(0));
}

TEST(Fog, FilterTintsWhatPassesEvenOverNoDepth) {
    const std::vector<scene::Fog> fogs{fog({1, 0.5, 0.25, 0.5, 0})};
    const FogEffect near = fog_along(fogs, kUp, 0.001, kGen);  // POV: 1, 0.749981, 0.624964
    EXPECT_NEAR(near.attenuation.y, 0.75, 1e-3);
    EXPECT_NEAR(near.attenuation.z, 0.625, 1e-3);
    // With media_attenuation POV gives 0.367941, 0.206958, 0.143709: the light's own fog
    // (on / off) is tinted alike.
    const FogEffect light = fog_along(fogs, kUp, 10, kGen);
    EXPECT_NEAR(light.attenuation.x, 0.367941 / 1.0, 1e-3);
    EXPECT_NEAR(light.attenuation.y, 0.206958 / 0.749981, 1e-3);
    EXPECT_NEAR(light.attenuation.z, 0.143709 / 0.624964, 1e-3);
}

TEST(Fog, TransmitIsTheLeastThatShowsThrough) {
    // POV: 0.599939 through fog of transmit 0.6 where exp(-1) alone would give 0.37.
    EXPECT_NEAR(fog_along({fog({0, 0, 0, 0, 0.6})}, kUp, 10, kGen).attenuation.x, 0.6, 1e-9);
}

TEST(Fog, GroundFogThinsAboveItsOffset) {
    scene::Fog f = fog({0, 0, 0, 0, 0});
    f.type = 2;
    f.offset = 5;
    f.alt = 1;
    // POV: 0.528649 (density 1 up to y = 5, 1 / (1 + (y - 5)²) above).
    EXPECT_NEAR(fog_along({f}, kUp, 10, kGen).attenuation.x, 0.528649, 1e-4);
}

TEST(Fog, ZeroDistanceMeansNoFog) {
    scene::Fog f = fog({1, 1, 1, 0, 0});
    f.distance = 0;
    const FogEffect e = fog_along({f}, kUp, 100, kGen);
    EXPECT_EQ(e.attenuation, glm::dvec3(1));
    EXPECT_EQ(e.added, glm::dvec3(0));
}

}  // namespace
}  // namespace lumen::render
