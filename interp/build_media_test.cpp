// media { } and density { } through the interpreter: POV-Ray 3.7's defaults per #version,
// where media may stand, densities (their order, transforms, density_map entries) and the
// located errors POV-Ray gives.
#include "interp/build_test_support.hpp"
#include "scene/media.hpp"

namespace lumen::interp::testing {
namespace {

using BuildMedia = BuildTest;

const scene::Media& first_media(const scene::Scene& s) {
    return *s.objects.at(0)->interior->media.at(0);
}

TEST_F(BuildMedia, DefaultsFollowTheVersion) {
    const scene::Scene now = run("#version 3.7;\nsphere { 0, 1 hollow interior { media { emission 1 } } }");
    const scene::Media& m = first_media(now);
    EXPECT_EQ(m.method, 3);
    EXPECT_EQ(m.intervals, 1);
    EXPECT_EQ(m.samples_min, 10);
    EXPECT_EQ(m.aa_level, 3);
    EXPECT_DOUBLE_EQ(m.emission.y, 1);
    const scene::Scene old = run("#version 3.1;\nsphere { 0, 1 hollow interior { media { emission 1 } } }");
    EXPECT_EQ(first_media(old).method, 1);
    EXPECT_EQ(first_media(old).intervals, 10);
    EXPECT_EQ(first_media(old).samples_max, 1);
}

TEST_F(BuildMedia, SettingsScatteringAndSeveralMedia) {
    const scene::Scene s = run(
        "#declare M = media { scattering { 5, rgb <0.1, 0.2, 0.3> eccentricity 0.4 extinction 0.5 } samples 4, 8 }\n"
        "box { -1, 1 hollow interior { media { M method 2 intervals 3 } media { absorption 0.5 } } }\n"
        "media { emission 0.01 }");
    const auto& list = s.objects.at(0)->interior->media;
    ASSERT_EQ(list.size(), 2u);
    EXPECT_EQ(list[0]->scattering_type, 5);
    EXPECT_DOUBLE_EQ(list[0]->eccentricity, 0.4);
    EXPECT_DOUBLE_EQ(list[0]->extinction, 0.5);
    EXPECT_DOUBLE_EQ(list[0]->scattering.z, 0.3);
    EXPECT_EQ(list[0]->samples_min, 4);
    EXPECT_EQ(list[0]->samples_max, 8);
    EXPECT_EQ(list[0]->method, 2);
    EXPECT_EQ(list[0]->intervals, 3);
    EXPECT_DOUBLE_EQ(list[1]->absorption.x, 0.5);
    ASSERT_EQ(s.atmosphere.size(), 1u);
    EXPECT_DOUBLE_EQ(s.atmosphere[0]->emission.x, 0.01);
    EXPECT_TRUE(s.unsupported.empty());
}

TEST_F(BuildMedia, DensitiesGoFirstAndMoveWithTheObject) {
    const scene::Scene s = run(
        "#declare D = density { rgb 0.5 }\n"
        "sphere { 0, 1 hollow interior { media { emission 1 density { spherical } density { D } } }"
        " translate <1, 2, 3> }");
    const scene::Media& m = first_media(s);
    ASSERT_EQ(m.densities.size(), 2u);
    EXPECT_TRUE(m.densities[0]->pattern.is_plain());  // the last written is first
    EXPECT_EQ(m.densities[1]->pattern.type(), scene::PatternType::Spherical);
    EXPECT_FALSE(m.densities[1]->pattern.steps.steps.empty());  // moved by the translate
}

TEST_F(BuildMedia, DensityMapTakesColoursOrDensities) {
    const scene::Scene colours = run(
        "sphere { 0, 1 hollow interior { media { emission 1 density { gradient x density_map { [0 rgb 0] [1 rgb 1] } } } } }");
    EXPECT_EQ(first_media(colours).densities.at(0)->colour_map.size(), 2u);
    const scene::Scene densities = run(
        "#declare A = density { rgb 1 }\n"
        "sphere { 0, 1 hollow interior { media { emission 1 density { gradient x density_map { [0 A] [1 rgb 0.2] } } } } }");
    const auto& d = first_media(densities).densities.at(0);
    ASSERT_EQ(d->pigment_map.size(), 2u);
    EXPECT_DOUBLE_EQ(d->pigment_map[1].item->colour.r, 0.2);
}

TEST_F(BuildMedia, LocatedErrors) {
    EXPECT_EQ(error_of("media { method 4 }"), "t.pov:1:16: error: media method must be 1, 2 or 3");
    EXPECT_NE(error_of("media { samples 0 }").find("media samples must be at least 1"), std::string::npos);
    EXPECT_NE(error_of("media { samples 5, 2 }").find("maximum samples are fewer than its minimum"),
              std::string::npos);
    EXPECT_NE(error_of("media { scattering { 1, 0.5 eccentricity 0.3 } }").find("eccentricity belongs to scattering type 5"),
              std::string::npos);
    EXPECT_NE(error_of("media { intervals 0 }").find("intervals must be at least 1"), std::string::npos);
    EXPECT_NE(error_of("media { aa_level 40 }").find("aa_level of at most 16"), std::string::npos);
    EXPECT_NE(error_of("media { intervals 5000 }").find("at most 1000 media intervals"), std::string::npos);
    EXPECT_NE(error_of("media { confidence 1 }").find("confidence must be in [0, 1)"), std::string::npos);
}

}  // namespace
}  // namespace lumen::interp::testing
