// texture, pigment, finish, normal, interior, material and maps.
#include "interp/build_test_support.hpp"

namespace lumen::interp::testing {
namespace {

using BuildMaterial = BuildTest;

TEST_F(BuildMaterial, PigmentColourAndIdent) {
    scene::Texture t = texture_of("#declare C = rgb <1,0.5,0>;\nsphere { 0, 1 pigment { C } }");
    EXPECT_EQ(t.pigment->colour, (scene::Colour{1, 0.5, 0, 0, 0}));
    scene::Texture g = texture_of("sphere { 0, 1 pigment { color 0.5 } }");
    EXPECT_EQ(g.pigment->colour, (scene::Colour{0.5, 0.5, 0.5, 0.5, 0.5}));
}

TEST_F(BuildMaterial, CheckerListFormWithColoursAndPigments) {
    scene::Texture t = texture_of("sphere { 0, 1 pigment { checker rgb 1, rgb <1,0,0> } }");
    EXPECT_EQ(t.pigment->pattern.type(), scene::PatternType::Checker);
    EXPECT_TRUE(t.pigment->list_form);
    ASSERT_EQ(t.pigment->colour_map.size(), 2u);
    EXPECT_DOUBLE_EQ(t.pigment->colour_map[1].value, 1);
    EXPECT_EQ(t.pigment->colour_map[1].item, (scene::Colour{1, 0, 0, 0, 0}));
    scene::Texture p = texture_of(
        "sphere { 0, 1 pigment { hexagon pigment { rgb 1 } pigment { checker } rgb 0.5 } }");
    ASSERT_EQ(p.pigment->pigment_map.size(), 3u);
    EXPECT_EQ(p.pigment->pigment_map[1].item->pattern.type(), scene::PatternType::Checker);
}

TEST_F(BuildMaterial, TilesIsACheckerOfTwoTexturesSecondFirst) {
    scene::Texture t = texture_of(
        "sphere { 0, 1 texture { tiles { texture { pigment { rgb 1 } } tile2 "
        "texture { pigment { rgb <1, 0, 0> } } } } }");
    EXPECT_TRUE(std::holds_alternative<scene::pattern::Checker>(t.pattern.kind));
    ASSERT_EQ(t.texture_map.size(), 2u);
    EXPECT_TRUE(t.list_form);
    // POV-Ray shows tile2's texture where checker shows its first entry (measured).
    const scene::Pigment& first = *t.texture_map[0].item.back()->pigment;
    EXPECT_EQ(first.colour.g, 0);
    EXPECT_EQ(error_of("sphere { 0, 1 texture { tiles { texture { } 1 } } }"),
              "t.pov:1:45: error: unexpected a float in tiles");
}

TEST_F(BuildMaterial, GradientColourMapInWrittenOrder) {
    scene::Texture t = texture_of(
        "sphere { 0, 1 pigment { gradient <0,2,0> color_map { [0.5 rgb 1] [0.2 rgb 0] "
        "[0.9 rgb <1,0,0>] } frequency 2 phase 0.1 sine_wave } }");
    const scene::Pigment& p = *t.pigment;
    expect_vec(std::get<scene::pattern::Gradient>(p.pattern.kind).direction, {0, 1, 0});
    ASSERT_EQ(p.colour_map.size(), 3u);
    EXPECT_DOUBLE_EQ(p.colour_map[0].value, 0.5);
    EXPECT_DOUBLE_EQ(p.colour_map[1].value, 0.2);
    EXPECT_DOUBLE_EQ(p.pattern.frequency, 2);
    EXPECT_EQ(p.pattern.phase, double(0.1f));  // single precision, as in POV
    EXPECT_EQ(p.pattern.wave, scene::WaveType::Sine);
}

TEST_F(BuildMaterial, OldColourMapBandForm) {
    scene::Texture t = texture_of(
        "sphere { 0, 1 pigment { onion color_map { [0 0.5 color rgb 1 color rgb 0] } } }");
    ASSERT_EQ(t.pigment->colour_map.size(), 2u);
    EXPECT_DOUBLE_EQ(t.pigment->colour_map[1].value, 0.5);
    EXPECT_EQ(t.pigment->colour_map[1].item, (scene::Colour{0, 0, 0, 0, 0}));
}

TEST_F(BuildMaterial, PigmentTransformMovesOnlyThePattern) {
    scene::ObjectPtr o = first_object("sphere { 0, 1 pigment { checker scale 2 } }");
    EXPECT_TRUE(o->transform.is_identity());
    expect_vec(o->texture[0]->pigment->pattern.steps.composed_transform().point({1, 1, 1}), {2, 2, 2});
}

TEST_F(BuildMaterial, NoisePatternsAndTurbulenceAreRendered) {
    scene::Texture t = texture_of("sphere { 0, 1 pigment { bozo turbulence 0.5 } }");
    EXPECT_EQ(t.pigment->pattern.type(), scene::PatternType::Bozo);
    EXPECT_FALSE(t.pigment->pattern.unsupported.has_value());
    expect_vec(t.pigment->pattern.steps.classic_turbulence()->amount, {0.5, 0.5, 0.5});
    scene::Texture g = texture_of("sphere { 0, 1 pigment { checker turbulence 0.2 } }");
    EXPECT_FALSE(g.pigment->pattern.unsupported.has_value());
}

TEST_F(BuildMaterial, FinishKeywords) {
    scene::Texture t = texture_of(
        "sphere { 0, 1 finish { ambient 0.2 emission rgb <1,0,0> diffuse 0.7, 0.1 brilliance 2 "
        "phong 0.5 phong_size 20 specular 0.3 roughness 0.01 metallic crand 0.1 "
        "reflection_exponent 2 conserve_energy irid { 0.3 thickness 0.2 turbulence 0.1 } } }");
    const scene::Finish& f = *t.finish;
    expect_vec(f.ambient, {0.2, 0.2, 0.2});
    expect_vec(f.emission, {1, 0, 0});
    EXPECT_DOUBLE_EQ(f.diffuse, 0.7);
    EXPECT_DOUBLE_EQ(f.diffuse_back, 0.1);
    EXPECT_DOUBLE_EQ(f.brilliance, 2);
    EXPECT_DOUBLE_EQ(f.phong_size, 20);
    EXPECT_DOUBLE_EQ(f.roughness, 0.01);
    EXPECT_DOUBLE_EQ(f.metallic, 1);
    EXPECT_DOUBLE_EQ(f.reflection_exponent, 2);
    EXPECT_TRUE(f.conserve_energy);
    EXPECT_DOUBLE_EQ(f.irid_amount, 0.3);
    EXPECT_DOUBLE_EQ(f.irid_thickness, 0.2);
}

TEST_F(BuildMaterial, IridTurbulenceIsRendered) {
    const scene::Scene s = run("sphere { 0, 1 finish { irid { 0.3 turbulence 0.5 } } }");
    EXPECT_TRUE(s.unsupported.empty());
    EXPECT_DOUBLE_EQ(s.objects[0]->texture.back()->finish->irid_turbulence, 0.5);
    // Also through a texture that adds a finish block to a declared one.
    const scene::Scene t = run("#declare T = texture { finish { irid { 0.3 } } }\n"
                               "sphere { 0, 1 texture { T finish { irid { 0.3 turbulence 1 } } } }");
    EXPECT_DOUBLE_EQ(t.objects[0]->texture.back()->finish->irid_turbulence, 1);
}

TEST_F(BuildMaterial, ReflectionForms) {
    const scene::Finish a = *texture_of("sphere { 0, 1 finish { reflection 0.3 } }").finish;
    expect_vec(a.reflection_min, {0.3, 0.3, 0.3});
    expect_vec(a.reflection_max, {0.3, 0.3, 0.3});
    const scene::Finish b = *texture_of(
        "sphere { 0, 1 finish { reflection { 0.1, 0.9 falloff 2 exponent 3 metallic 0.5 } } }")
                                 .finish;
    expect_vec(b.reflection_min, {0.1, 0.1, 0.1});
    expect_vec(b.reflection_max, {0.9, 0.9, 0.9});
    EXPECT_DOUBLE_EQ(b.reflection_falloff, 2);
    EXPECT_DOUBLE_EQ(b.reflection_exponent, 3);
    EXPECT_DOUBLE_EQ(b.reflection_metallic, 0.5);
    const scene::Finish c = *texture_of("sphere { 0, 1 finish { reflection { 1 fresnel } } }").finish;
    expect_vec(c.reflection_min, {0, 0, 0});
    EXPECT_TRUE(c.fresnel);
}

TEST_F(BuildMaterial, AlbedoUsesFinalBrilliance) {
    const scene::Finish f =
        *texture_of("sphere { 0, 1 finish { diffuse albedo 0.6 brilliance 3 } }").finish;
    EXPECT_DOUBLE_EQ(f.diffuse, 0.6 * 2);
}

TEST_F(BuildMaterial, FinishIdentCopiesAndModifies) {
    const scene::Finish f = *texture_of(
        "#declare F = finish { phong 1 }\nsphere { 0, 1 finish { F specular 0.5 } }").finish;
    EXPECT_DOUBLE_EQ(f.phong, 1);
    EXPECT_DOUBLE_EQ(f.specular, 0.5);
}

TEST_F(BuildMaterial, ObsoleteFinishIorIsKept) {
    const scene::Finish f = *texture_of("sphere { 0, 1 finish { ior 1.5 } }").finish;
    ASSERT_TRUE(f.ior.has_value());
    EXPECT_DOUBLE_EQ(*f.ior, 1.5);
}

TEST_F(BuildMaterial, PavementNormalIsDifferenced) {
    scene::Texture t = texture_of("sphere { 0, 1 normal { pavement bump_size 0.4 scale 0.2 } }");
    EXPECT_EQ(t.normal->pattern.type(), scene::PatternType::Pavement);
    EXPECT_EQ(t.normal->amount, double(0.4f));  // POV keeps it in single precision
    EXPECT_FALSE(t.normal->pattern.unsupported.has_value());
}

TEST_F(BuildMaterial, TextureIdentCopiesAndAcceptsModifiers) {
    scene::Texture t = texture_of(
        "#declare T = texture { pigment { rgb 1 } finish { phong 1 } }\n"
        "sphere { 0, 1 texture { T finish { phong 0.5 } } }");
    EXPECT_EQ(t.pigment->colour, (scene::Colour{1, 1, 1, 0, 0}));
    EXPECT_DOUBLE_EQ(t.finish->phong, 0.5);
}

TEST_F(BuildMaterial, CheckerTexturesAndTextureMap) {
    scene::Texture t = texture_of(
        "sphere { 0, 1 texture { checker texture { pigment { rgb 1 } } "
        "texture { pigment { rgb 0 } } } }");
    EXPECT_TRUE(t.list_form);
    ASSERT_EQ(t.texture_map.size(), 2u);
    scene::Texture m = texture_of(
        "sphere { 0, 1 texture { gradient y texture_map { [0 pigment { rgb 1 }] "
        "[1 pigment { rgb 0 } finish { phong 1 }] } } }");
    ASSERT_EQ(m.texture_map.size(), 2u);
    EXPECT_DOUBLE_EQ(m.texture_map[1].item[0]->finish->phong, 1);
}

TEST_F(BuildMaterial, PigmentMap) {
    scene::Texture t = texture_of(
        "sphere { 0, 1 pigment { radial pigment_map { [0 rgb 1] [1 checker rgb 0, rgb 1] } } }");
    ASSERT_EQ(t.pigment->pigment_map.size(), 2u);
    EXPECT_EQ(t.pigment->pigment_map[1].item->pattern.type(), scene::PatternType::Checker);
}

TEST_F(BuildMaterial, InteriorAndMaterial) {
    scene::ObjectPtr o = first_object(
        "sphere { 0, 1 interior { ior 1.5 caustics 0.5 dispersion 1.1 dispersion_samples 9 "
        "fade_distance 2 fade_power 1001 fade_color rgb <1,0,0> } }");
    ASSERT_TRUE(o->interior.has_value());
    EXPECT_DOUBLE_EQ(o->interior->ior, 1.5);
    EXPECT_EQ(o->interior->dispersion_samples, 9);
    expect_vec(o->interior->fade_colour, {1, 0, 0});
    scene::ObjectPtr m = first_object(
        "sphere { 0, 1 material { texture { pigment { rgbf 1 } } interior { ior 1.33 } "
        "interior_texture { pigment { rgb 1 } } } }");
    ASSERT_TRUE(m->interior.has_value());
    EXPECT_DOUBLE_EQ(m->interior->ior, 1.33);
    EXPECT_EQ(m->texture.size(), 1u);
    EXPECT_EQ(m->interior_texture.size(), 1u);
}

TEST_F(BuildMaterial, InteriorKeepsItsMedia) {
    scene::Scene s = run("sphere { 0, 1 hollow material { interior { media { emission 1 } media { } } } }");
    EXPECT_TRUE(s.unsupported.empty());
    ASSERT_TRUE(s.objects.at(0)->interior);
    EXPECT_EQ(s.objects.at(0)->interior->media.size(), 2u);
}

TEST_F(BuildMaterial, DefaultFinishApplies) {
    scene::Texture t = texture_of("#default { finish { ambient 0.3 } }\nsphere { 0, 1 pigment { rgb 1 } }");
    ASSERT_TRUE(t.finish);
    expect_vec(t.finish->ambient, {0.3, 0.3, 0.3});
}

TEST_F(BuildMaterial, Errors) {
    EXPECT_EQ(error_of("sphere { 0, 1 finish { phong_size 2 checker } }"),
              "t.pov:1:37: error: 'checker' is not a finish keyword");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { color_map { [0.5] } } }"),
              "t.pov:1:38: error: expected a colour in color_map entry, found the end of the block");
}

}  // namespace
}  // namespace lumen::interp::testing

namespace lumen::interp::testing {
namespace {

using BuildMaterialForms = BuildTest;

TEST_F(BuildMaterialForms, ColourComponentKeywordsInPigment) {
    scene::Texture t = texture_of("sphere { 0, 1 pigment { red 0.75 green 0.5 blue 0.25 filter 0.1 } }");
    EXPECT_EQ(t.pigment->colour, (scene::Colour{0.75, 0.5, 0.25, 0.1, 0}));
}

TEST_F(BuildMaterialForms, AverageMapEntriesMayOmitTheirWeight) {
    scene::Texture t = texture_of(
        "sphere { 0, 1 pigment { average pigment_map { [gradient x] [2 checker] } } }");
    ASSERT_EQ(t.pigment->pigment_map.size(), 2u);
    EXPECT_DOUBLE_EQ(t.pigment->pigment_map[0].value, 1);
    EXPECT_DOUBLE_EQ(t.pigment->pigment_map[1].value, 2);
    EXPECT_FALSE(t.pigment->pattern.unsupported.has_value());
}

TEST_F(BuildMaterialForms, RepeatWarpsRender) {
    scene::Texture t = texture_of("sphere { 0, 1 pigment { checker warp { repeat x } } }");
    EXPECT_FALSE(t.pigment->pattern.unsupported.has_value());
}

TEST_F(BuildMaterialForms, ObjectOfADeclaredLightIsALight) {
    scene::Scene s = run("#declare L = light_source { 0, 1 }\nobject { L translate y }");
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_TRUE(s.objects.empty());
    expect_vec(s.lights[0].position, {0, 1, 0});
}

}  // namespace
}  // namespace lumen::interp::testing

namespace lumen::interp::testing {
namespace {

using BuildFinishLayering = BuildTest;

TEST_F(BuildFinishLayering, FinishBlockModifiesTheFinishInPlace) {
    const char* decl = "#declare T = texture { pigment { rgb 1 } finish { ambient 0.3 phong 1 } }\n";
    scene::Texture t = texture_of(std::string(decl) + "sphere { 0, 1 texture { T finish { specular 0.5 } } }");
    expect_vec(t.finish->ambient, {0.3, 0.3, 0.3});  // kept from T
    EXPECT_DOUBLE_EQ(t.finish->phong, 1);
    EXPECT_DOUBLE_EQ(t.finish->specular, 0.5);
    scene::Texture o = texture_of(std::string(decl) + "sphere { 0, 1 texture { T } finish { phong 0.2 } }");
    expect_vec(o.finish->ambient, {0.3, 0.3, 0.3});
    EXPECT_DOUBLE_EQ(o.finish->phong, 0.2);
}

TEST_F(BuildFinishLayering, DeclaredFinishReplacesWhole) {
    scene::Texture t = texture_of(
        "#declare F = finish { specular 0.5 }\n"
        "#declare T = texture { pigment { rgb 1 } finish { ambient 0.3 } }\n"
        "sphere { 0, 1 texture { T finish { F } } }");
    expect_vec(t.finish->ambient, {0.1, 0.1, 0.1});
    EXPECT_DOUBLE_EQ(t.finish->specular, 0.5);
}

}  // namespace
}  // namespace lumen::interp::testing
