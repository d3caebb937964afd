// global_settings, background, fog, sky_sphere, the unsupported list and the JSON dump.
#include "interp/build_test_support.hpp"

namespace lumen::interp::testing {
namespace {

using BuildScene = BuildTest;

TEST_F(BuildScene, GlobalSettings) {
    scene::GlobalSettings g =
        run("global_settings { assumed_gamma 1.0 max_trace_level 300 adc_bailout 0.01 "
            "ambient_light rgb <1,0,0> irid_wavelength rgb 0.5 noise_generator 1 "
            "number_of_waves 5 charset utf8 }")
            .globals;
    ASSERT_TRUE(g.assumed_gamma.has_value());
    EXPECT_DOUBLE_EQ(*g.assumed_gamma, 1.0);
    EXPECT_EQ(g.max_trace_level, 256);  // clamped
    EXPECT_DOUBLE_EQ(g.adc_bailout, 0.01);
    expect_vec(g.ambient_light, {1, 0, 0});
    EXPECT_EQ(g.noise_generator, 1);
    EXPECT_EQ(g.number_of_waves, 5);
}

TEST_F(BuildScene, OnlyFirstAssumedGammaCounts) {
    scene::GlobalSettings g =
        run("global_settings { assumed_gamma 2.2 }\nglobal_settings { assumed_gamma 1 }").globals;
    EXPECT_DOUBLE_EQ(*g.assumed_gamma, 2.2);
    EXPECT_FALSE(warnings.empty());
}

TEST_F(BuildScene, RadiosityAndPhotons) {
    scene::Scene s = run("global_settings { radiosity { count 100, 2000 error_bound 0.5 "
                         "always_sample off brightness 2 } photons { count 1000 } }");
    ASSERT_TRUE(s.globals.radiosity.has_value());
    EXPECT_EQ(s.globals.radiosity->count, 100);
    EXPECT_EQ(s.globals.radiosity->count_pool, 2000);
    EXPECT_DOUBLE_EQ(s.globals.radiosity->brightness, 2);
    ASSERT_TRUE(s.globals.photons.has_value());
    EXPECT_EQ(s.globals.photons->count, 1000);
    EXPECT_TRUE(s.unsupported.empty());
    EXPECT_EQ(run("global_settings { photons { spacing 0.1 media 100, 2 } }").globals.photons->media_steps,
              100);
    // lumen's photon files hold no media photons: listed where media is written. Photon files
    // are kept with the place they are named at.
    const scene::Scene m = run("global_settings { photons { spacing 0.1 media 100, 2 "
                               "save_file \"p.ph\" } }");
    ASSERT_EQ(m.unsupported.size(), 1u);
    EXPECT_EQ(m.unsupported[0].feature, "photons media with save_file or load_file");
    EXPECT_EQ(m.unsupported[0].loc.column, 41u);  // at `media`
    EXPECT_EQ(m.globals.photons->save_file, "p.ph");
    EXPECT_EQ(m.globals.photons->file_loc.column, 54u);
}

TEST_F(BuildScene, BackgroundPremultipliedByTransmit) {
    scene::Colour b = run("background { rgbt <1, 0.5, 0, 0.5> }").background;
    EXPECT_EQ(b, (scene::Colour{0.5, 0.25, 0, 0, 0.5}));
}

TEST_F(BuildScene, FogGround) {
    scene::Scene s = run("fog { fog_type 2 distance 10 color rgb <0.5,0.5,0.5> fog_offset 1 "
                         "fog_alt 2 up z translate y }");
    ASSERT_EQ(s.fogs.size(), 1u);
    const scene::Fog& f = s.fogs[0];
    EXPECT_EQ(f.type, 2);
    EXPECT_DOUBLE_EQ(f.distance, 10);
    EXPECT_DOUBLE_EQ(f.alt, 2);
    expect_vec(f.up, {0, 0, 1});
    EXPECT_FALSE(f.transform.is_identity());
    EXPECT_TRUE(s.unsupported.empty());
    const scene::Scene t = run("fog { distance 1 turbulence 0.5 turb_depth 0.3 octaves 3 omega 0.6 "
                               "lambda 2.2 }");
    EXPECT_TRUE(t.unsupported.empty());
    const scene::TurbulenceParams& turb = t.fogs[0].turbulence;
    expect_vec(turb.amount, {0.5, 0.5, 0.5});
    EXPECT_EQ(turb.octaves, 3);
    EXPECT_EQ(turb.omega, double(0.6f));
    EXPECT_EQ(turb.lambda, double(2.2f));
    EXPECT_DOUBLE_EQ(t.fogs[0].turb_depth, 0.3);
}

TEST_F(BuildScene, SkySphere) {
    scene::Scene s = run("sky_sphere { pigment { gradient y } pigment { rgbt 1 } rotate x*10 emission 2 }");
    ASSERT_TRUE(s.sky_sphere.has_value());
    EXPECT_EQ(s.sky_sphere->pigments.size(), 2u);
    EXPECT_DOUBLE_EQ(s.sky_sphere->emission, 2);
    EXPECT_FALSE(s.sky_sphere->transform.is_identity());
}

TEST_F(BuildScene, RainbowAndItsIdentifier) {
    scene::Scene s = run("#declare R = rainbow { angle 42.5 width 5 distance 1e7 direction <-0.2, -0.2, 1>\n"
                         "  jitter 0.01 colour_map { [0 rgb 1 filter 1] [0.9 rgb <1, 0.2, 0.2>] } }\n"
                         "rainbow { R }\nrainbow { R angle 37 up z }\n");
    ASSERT_EQ(s.rainbows.size(), 2u);
    const scene::Rainbow& r = s.rainbows[0];
    EXPECT_DOUBLE_EQ(r.angle, 42.5);
    EXPECT_DOUBLE_EQ(r.width, 5);
    EXPECT_DOUBLE_EQ(r.distance, 1e7);
    EXPECT_DOUBLE_EQ(r.jitter, 0.01);
    expect_vec(r.direction, {-0.2, -0.2, 1});
    ASSERT_EQ(r.colour_map.size(), 2u);
    EXPECT_DOUBLE_EQ(r.colour_map[1].value, 0.9);
    EXPECT_DOUBLE_EQ(s.rainbows[1].angle, 37);
    EXPECT_DOUBLE_EQ(s.rainbows[1].width, 5);
    expect_vec(s.rainbows[1].up, {0, 0, 1});
    EXPECT_TRUE(s.unsupported.empty());
    EXPECT_EQ(error_of("rainbow { angle 20 fog_type 2 }").substr(0, 19), "t.pov:1:20: error: ");
}

// arc_angle makes a partial arc, falloff_angle defaulting to it; falloff_angle alone changes
// nothing; POV-Ray's checks (probed): each angle in 0..360, the arc no smaller than the
// falloff, an up vector that is neither zero nor along the direction (arc or not).
TEST_F(BuildScene, RainbowArcAndItsChecks) {
    scene::Scene s = run("rainbow { angle 40 width 5 arc_angle 120 }\n"
                         "rainbow { angle 40 width 5 falloff_angle 30 arc_angle 90 }\n"
                         "rainbow { angle 40 width 5 falloff_angle 30 }\n");
    ASSERT_EQ(s.rainbows.size(), 3u);
    ASSERT_TRUE(s.rainbows[0].arc);
    EXPECT_DOUBLE_EQ(s.rainbows[0].arc->arc_angle, 120);
    EXPECT_DOUBLE_EQ(s.rainbows[0].arc->falloff_angle, 120);
    ASSERT_TRUE(s.rainbows[1].arc);
    EXPECT_DOUBLE_EQ(s.rainbows[1].arc->arc_angle, 90);
    EXPECT_DOUBLE_EQ(s.rainbows[1].arc->falloff_angle, 30);
    EXPECT_FALSE(s.rainbows[2].arc);
    EXPECT_TRUE(s.unsupported.empty());
    EXPECT_NE(error_of("rainbow { angle 40 arc_angle 400 }").find("1:20: error: illegal arc_angle"),
              std::string::npos);
    EXPECT_NE(error_of("rainbow { falloff_angle -1 }").find("illegal falloff_angle"),
              std::string::npos);
    EXPECT_NE(error_of("rainbow { arc_angle 90 falloff_angle 120 }").find("smaller than"),
              std::string::npos);
    EXPECT_NE(error_of("rainbow { up 0 }").find("up vector is zero"), std::string::npos);
    EXPECT_NE(error_of("rainbow { direction z up z }").find("co-linear"), std::string::npos);
}

TEST_F(BuildScene, UnsupportedListInSourceOrderWithoutDuplicates) {
    scene::Scene s = run(
        "#declare P = pigment { facets }\n"
        "sphere { 0, 1 pigment { P } }\n"
        "sphere { 0, 1 pigment { P } }\n"
        "global_settings { mm_per_unit 40 }\n"
        "lemon { <0, 0, 0>, <0, 1, 0>, 1, 0.5 }\n");
    ASSERT_EQ(s.unsupported.size(), 3u);
    EXPECT_EQ(s.unsupported[0].feature, "pattern 'facets'");
    EXPECT_EQ(s.unsupported[1].feature, "subsurface");
    EXPECT_EQ(s.unsupported[2].feature, "lemon");
    EXPECT_EQ(s.unsupported[2].loc.line, 5u);
}

TEST_F(BuildScene, TopLevelValueThatCannotStandAlone) {
    EXPECT_EQ(error_of("pigment { rgb 1 }"), "t.pov:1:1: error: a pigment cannot stand at top level");
}

TEST_F(BuildScene, DumpPrintsOnlyNonDefaults) {
    std::string json = dump_scene_json(run("sphere { <0,-0,1>, 1 }"));
    EXPECT_EQ(json,
              "{\n"
              "  \"objects\": [\n"
              "    {\n"
              "      \"loc\": \"t.pov:1:1\",\n"
              "      \"type\": \"sphere\",\n"
              "      \"center\": [0, 0, 1]\n"
              "    }\n"
              "  ]\n"
              "}\n");
}

TEST_F(BuildScene, UntexturedObjectsTakeTheDefaultInEffectWhereTheyArePlaced) {
    // As in POV-Ray (iortest.pov relies on it): the declaration comes before the #default.
    const scene::Scene s = run("#declare S = union { sphere { 0, 1 } sphere { x, 1 } }\n"
                               "object { S }\n"
                               "#default { texture { pigment { rgb <1,0,0> } finish { ambient 1 } } }\n"
                               "object { S translate y }\n"
                               "sphere { 0, 1 pigment { rgb 1 } }");
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_TRUE(s.objects[0]->texture.empty());
    ASSERT_EQ(s.objects[1]->texture.size(), 1u);
    const scene::Texture& t = *s.objects[1]->texture[0];
    ASSERT_TRUE(t.pigment && t.finish);
    EXPECT_EQ(t.pigment->colour, (scene::Colour{1, 0, 0, 0, 0}));
    expect_vec(t.finish->ambient, {1, 1, 1});
    EXPECT_EQ(s.objects[2]->texture.back()->pigment->colour, (scene::Colour{1, 1, 1, 0, 0}));
}

TEST_F(BuildScene, DumpEmptySceneIsEmptyObject) {
    EXPECT_EQ(dump_scene_json(scene::Scene{}), "{}\n");
}

TEST_F(BuildScene, DumpIsDeterministic) {
    const char* text = "union { sphere { 0, 1 } box { 0, 1 } pigment { checker } rotate 30 }";
    EXPECT_EQ(dump_scene_json(run(text)), dump_scene_json(run(text)));
}

}  // namespace
}  // namespace lumen::interp::testing

namespace lumen::interp::testing {
namespace {

using BuildSceneOld = BuildTest;

TEST_F(BuildSceneOld, DefaultBlockWithoutHashActsLikeHashDefault) {
    scene::Texture t = texture_of("default { finish { ambient 0.4 } }\nsphere { 0, 1 pigment { rgb 1 } }");
    ASSERT_TRUE(t.finish);
    expect_vec(t.finish->ambient, {0.4, 0.4, 0.4});
}

}  // namespace
}  // namespace lumen::interp::testing
