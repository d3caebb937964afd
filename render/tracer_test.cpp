// Whole-image checks of the tracer against POV-Ray 3.7 renders (render/testdata).
#include <gtest/gtest.h>

#include "base/diagnostics.hpp"
#include "render/shade_test_support.hpp"

namespace lumen::render::test {
namespace {

constexpr int kW = 48, kH = 36;

scene::Scene v1_scene(bool version_37) {
    scene::Scene s = version_37 ? scene_37() : scene::Scene{};
    s.camera.location = {0, 0, -5};
    s.lights.push_back(point_light({0, 0, -100}, {1, 1, 1}));
    s.objects.push_back(sphere({0, 0, 0}, 1, {rgb(1, 1, 1)}));
    return s;
}

// The common stage of several references: camera <0,1,-5> looking at <0,0.5,0>.
scene::Scene stage() {
    scene::Scene s = scene_37();
    s.camera = look_at_camera({0, 1, -5}, {0, 0.5, 0});
    return s;
}

scene::Scene reflection_scene() {
    scene::Scene s = stage();
    s.lights.push_back(point_light({-4, 6, -5}, {1, 1, 1}));
    s.background = rgb(0.2, 0.3, 0.5);
    Material floor;
    floor.pigment = checker(rgb(1, 1, 1), rgb(0.1, 0.1, 0.1));
    s.objects.push_back(plane({0, 1, 0}, -1, floor));
    Material gold{rgb(0.9, 0.7, 0.3)};
    gold.finish.reflection_min = glm::dvec3(0.1);
    gold.finish.reflection_max = glm::dvec3(0.9);
    gold.finish.reflection_falloff = 2;
    s.objects.push_back(sphere({-1, 0, 0}, 1, gold));
    Material blue{rgb(0.3, 0.6, 0.9)};
    blue.finish.reflection_min = blue.finish.reflection_max = glm::dvec3(0.5);
    blue.finish.reflection_metallic = 1;
    blue.finish.phong = 0.5;
    s.objects.push_back(sphere({1.2, 0, 0.5}, 1, blue));
    return s;
}

void expect_matches(const scene::Scene& s, const std::string& reference, int max_diff,
                    RenderOptions opts = {}) {
    const Image8 ours = render8(s, kW, kH, opts);
    const Image8 pov = read_reference(reference);
    ASSERT_EQ(pov.width, kW) << reference;
    const Comparison c = compare(ours, pov);
    EXPECT_LE(c.max_diff, max_diff) << reference << ": " << c.differing << " values differ";
    EXPECT_GE(c.psnr, 45.0) << reference;
}

// Stands in for the radiosity solution: the same incident light everywhere.
class ConstantIndirect final : public IndirectLight {
public:
    explicit ConstantIndirect(double g) : g_(g) {}
    glm::dvec3 incident(const Hit&, const glm::dvec3&, ThreadState&) const override {
        return glm::dvec3(g_);
    }

private:
    double g_;
};

TEST(Tracer, IndirectLightTakesAmbientsPlaceScaledByDiffuseAndPigment) {
    // Radiosity (3.7): ambient is dropped and diffuse × pigment × G added, so G = 0.5 with
    // diffuse 0.6 looks exactly like ambient 0.3 without radiosity.
    Material m{rgb(0.8, 0.4, 1.0)};
    m.finish.diffuse = 0.6;
    m.finish.ambient = glm::dvec3(0.3);
    scene::Scene plain = scene_37();
    plain.camera.location = {0, 0, -5};
    plain.objects.push_back(sphere({0, 0, 0}, 1, m));
    scene::Scene rad = plain;
    rad.globals.radiosity = scene::RadiositySettings{};
    const ConstantIndirect half(0.5), none(0.0);
    RenderOptions with;
    with.indirect = &half;
    RenderOptions without;
    without.indirect = &none;
    const Image8 a = render8(plain, 16, 12), b = render8(rad, 16, 12, with),
                 c = render8(rad, 16, 12, without);
    for (int ch = 0; ch < 3; ++ch) {
        EXPECT_GT(a.at(8, 6, ch), 0);
        EXPECT_EQ(b.at(8, 6, ch), a.at(8, 6, ch)) << ch;
        EXPECT_EQ(c.at(8, 6, ch), 0) << ch;  // ambient 0.3 is gone under radiosity
    }
}

TEST(Tracer, DiffuseSphereCentreEncodesLikePovRay) {
    // V1: linear 0.1 + 0.6·N·L ≈ 0.7 at the centre pixel.
    EXPECT_EQ(render8(v1_scene(true), 64, 48).at(32, 24, 0), 218);
    EXPECT_EQ(render8(v1_scene(false), 64, 48).at(32, 24, 0), 178);
    scene::Scene g22 = v1_scene(true);
    g22.globals.assumed_gamma = 2.2;
    EXPECT_EQ(render8(g22, 64, 48).at(32, 24, 0), 180);
}

TEST(Tracer, DiffuseSphereMatchesWholeImage) {
    expect_matches(v1_scene(true), "v1.ppm", 0);
    expect_matches(v1_scene(false), "v1legacy.ppm", 0);
}

TEST(Tracer, PhongSpecularMetallicAndFadedLight) {
    scene::Scene s = scene_37();
    s.camera.location = {0, 0, -5};
    s.lights.push_back(point_light({-3, 4, -6}, {1, 0.9, 0.8}));
    scene::Light faded = point_light({4, 1, -3}, glm::dvec3(0.5));
    faded.fade_distance = 4;
    faded.fade_power = 2;
    s.lights.push_back(faded);
    Material red{rgb(0.8, 0.3, 0.2)};
    red.finish.phong = 0.8;
    red.finish.phong_size = 20;
    s.objects.push_back(sphere({-1.1, 0, 0}, 1, red));
    Material blue{rgb(0.2, 0.5, 0.9)};
    blue.finish.specular = 0.7;
    blue.finish.roughness = 0.02;
    blue.finish.brilliance = 2;
    blue.finish.metallic = 0.7;
    s.objects.push_back(sphere({1.1, 0, 0}, 1, blue));
    expect_matches(s, "hilite.ppm", 0);
}

TEST(Tracer, ReflectionFalloffAndMetallic) { expect_matches(reflection_scene(), "refl.ppm", 1); }

TEST(Tracer, GlassFresnelTotalInternalReflectionAndFade) {
    scene::Scene s = stage();
    s.lights.push_back(point_light({-4, 6, -5}, {1, 1, 1}));
    s.background = rgb(0.2, 0.3, 0.5);
    Material floor;
    floor.pigment = checker(rgb(1, 1, 1), rgb(0.1, 0.1, 0.1));
    s.objects.push_back(plane({0, 1, 0}, -1, floor));
    Material glass{{1, 1, 1, 0.9, 0}};
    glass.finish.phong = 0.9;
    glass.finish.reflection_min = glm::dvec3(0.05);
    glass.finish.reflection_max = glm::dvec3(1);
    glass.finish.fresnel = true;
    glass.finish.conserve_energy = true;
    glass.interior = scene::Interior{};
    glass.interior->ior = 1.5;
    s.objects.push_back(sphere({-1, 0, 0}, 1, glass));
    Material tinted{{0.8, 1, 0.8, 0, 0.8}};
    tinted.interior = scene::Interior{};
    tinted.interior->ior = 1.3;
    tinted.interior->fade_distance = 1;
    tinted.interior->fade_power = 2;
    tinted.interior->fade_colour = {0.5, 0.2, 0.2};
    s.objects.push_back(sphere({1.2, 0, 0.5}, 1, tinted));
    expect_matches(s, "glass.ppm", 1);
}

TEST(Tracer, ShadowsThroughFilterAndTransmit) {
    scene::Scene s = stage();
    s.lights.push_back(point_light({-2, 6, -3}, {1, 1, 1}));
    s.objects.push_back(plane({0, 1, 0}, -1, {rgb(0.9, 0.9, 0.9)}));
    s.objects.push_back(sphere({-1.2, 0, 0}, 0.8, {{0.5, 0.5, 0.5, 0, 0.5}}));
    s.objects.push_back(sphere({1.2, 0, 0}, 0.8, {{1, 0.2, 0.2, 0.8, 0}}));
    expect_matches(s, "shadow.ppm", 0);
}

TEST(Tracer, SpotlightAndShadowlessFadedLight) {
    scene::Scene s = stage();
    scene::Light spot = point_light({0, 5, -2}, glm::dvec3(1.5));
    spot.type = scene::LightType::Spot;
    spot.point_at = {0, -1, 1};
    spot.radius = 15;
    spot.falloff = 35;
    spot.tightness = 5;
    spot.fade_distance = 3;
    spot.fade_power = 2;
    s.lights.push_back(spot);
    scene::Light fill = point_light({3, 3, -3}, {0.3, 0.3, 0.6});
    fill.fade_distance = 1.5;
    fill.fade_power = 1;
    fill.shadowless = true;
    s.lights.push_back(fill);
    s.objects.push_back(plane({0, 1, 0}, -1, {rgb(0.9, 0.9, 0.9)}));
    Material m{rgb(0.9, 0.5, 0.3)};
    m.finish.phong = 0.6;
    s.objects.push_back(sphere({0, 0, 1}, 1, m));
    expect_matches(s, "spot.ppm", 0);
}

TEST(Tracer, AreaLight3x3) {
    scene::Scene s = stage();
    scene::Light l = point_light({-2, 5, -3}, {1, 1, 1});
    l.area = scene::AreaLight{{2, 0, 0}, {0, 0, 2}, 3, 3};
    s.lights.push_back(l);
    s.objects.push_back(plane({0, 1, 0}, -1, {rgb(0.9, 0.9, 0.9)}));
    s.objects.push_back(sphere({0, 0, 0}, 1, {rgb(0.9, 0.5, 0.3)}));
    expect_matches(s, "area.ppm", 2);
}

// +A0.1 +R3 -J with the given +AM method (deterministic, so POV's image is exact).
RenderOptions antialias_without_jitter(int method) {
    RenderOptions o;
    o.antialias = true;
    o.aa_threshold = 0.1;
    o.aa_method = method;
    o.aa_depth = 3;
    o.jitter = false;
    return o;
}

TEST(Tracer, AntialiasMethod1WithoutJitter) {
    expect_matches(reflection_scene(), "refl_am1.ppm", 1, antialias_without_jitter(1));
}

TEST(Tracer, AntialiasMethod2WithoutJitter) {
    expect_matches(reflection_scene(), "refl_am2.ppm", 1, antialias_without_jitter(2));
}

TEST(Tracer, MaxTraceLevelBetweenFacingMirrors) {
    // Two mirrors (reflection 0.5, ambient 0.5, diffuse 0) facing each other; values from
    // povray 3.7 with max_trace_level 2, 5 and 10 (#version 3.7, assumed_gamma 1).
    auto mirrors = [](int level) {
        scene::Scene s = scene_37();
        s.camera.location = {0, 0, -5};
        s.globals.max_trace_level = level;
        Material m{rgb(1, 0.5, 0)};
        m.finish.ambient = glm::dvec3(0.5);
        m.finish.diffuse = 0;
        m.finish.reflection_min = m.finish.reflection_max = glm::dvec3(0.5);
        s.objects.push_back(plane({0, 0, 1}, 2, m));
        s.objects.push_back(plane({0, 0, 1}, -8, m));
        return render8(s, 8, 6);
    };
    const Image8 two = mirrors(2), five = mirrors(5), ten = mirrors(10);
    EXPECT_EQ(two.at(4, 3, 0), 225);
    EXPECT_EQ(two.at(4, 3, 1), 165);
    EXPECT_EQ(five.at(4, 3, 0), 251);
    EXPECT_EQ(five.at(4, 3, 1), 185);
    EXPECT_EQ(ten.at(4, 3, 0), 255);
    EXPECT_EQ(ten.at(4, 3, 1), 187);
}

TEST(Tracer, FakeCausticsBrightenShadows) {
    scene::Scene s = stage();
    s.lights.push_back(point_light({-2, 6, -3}, {1, 1, 1}));
    s.objects.push_back(plane({0, 1, 0}, -1, {rgb(0.9, 0.9, 0.9)}));
    Material glass{{1, 1, 1, 0.9, 0}};
    glass.interior = scene::Interior{};
    glass.interior->ior = 1.5;
    glass.interior->caustics = 1.0;
    s.objects.push_back(sphere({0, 0, 0}, 0.9, glass));
    expect_matches(s, "caustics.ppm", 1);
}

scene::Scene fog_stage() {
    scene::Scene s = stage();
    s.lights.push_back(point_light({-4, 6, -5}, {1, 1, 1}));
    s.background = rgb(0.2, 0.3, 0.5);
    Material floor;
    floor.pigment = checker(rgb(1, 1, 1), rgb(0.1, 0.1, 0.1));
    s.objects.push_back(plane({0, 1, 0}, -1, floor));
    s.objects.push_back(sphere({0, 0, 2}, 1, {rgb(0.9, 0.5, 0.3)}));
    return s;
}

TEST(Tracer, ConstantFog) {
    scene::Scene s = fog_stage();
    scene::Fog fog;
    fog.distance = 6;
    fog.colour = rgb(0.5, 0.6, 0.7);
    s.fogs.push_back(fog);
    expect_matches(s, "fog.ppm", 1);
}

TEST(Tracer, GroundFogWithTransmit) {
    scene::Scene s = fog_stage();
    scene::Fog fog;
    fog.type = 2;
    fog.distance = 3;
    fog.colour = {0.8, 0.8, 0.8, 0, 0.1};
    fog.offset = -0.5;
    fog.alt = 0.5;
    s.fogs.push_back(fog);
    expect_matches(s, "groundfog.ppm", 1);
}

TEST(Tracer, InteriorTextureShadesTheBackOfSurfacesAndTheirShadows) {
    // Camera inside a red sphere whose inside is green; a white sphere (blue inside) seen from
    // outside; a clear sphere with a black inside, seen as a black disc and casting a shadow.
    scene::Scene s = scene_37();
    s.camera = look_at_camera({0, 0, -2}, {0, 0, 0});
    s.lights.push_back(point_light({1, 1, -1}, {1, 1, 1}));
    auto with_inside = [](scene::ObjectPtr o, const Material& inside) {
        auto copy = std::make_shared<scene::Object>(*o);
        copy->interior_texture = texture_of(inside);
        return scene::ObjectPtr(copy);
    };
    s.objects.push_back(with_inside(sphere({0, 0, 0}, 4, {rgb(1, 0, 0)}), {rgb(0, 1, 0)}));
    s.objects.push_back(with_inside(sphere({0.5, 0, 1}, 0.5, {rgb(1, 1, 1)}), {rgb(0, 0, 1)}));
    s.objects.push_back(
        with_inside(sphere({-0.6, 0.2, 0.5}, 0.4, {{1, 1, 1, 0, 1}}), {rgb(0, 0, 0)}));
    expect_matches(s, "inttex.ppm", 0);
}

TEST(Tracer, ProjectedThroughLightsOnlyPassThroughTheirObject) {
    // A spot of light through a sphere half way to the light, and a shadowless fill light
    // projected through a smaller sphere.
    scene::Scene s = scene_37();
    s.camera = look_at_camera({0, 3, -4}, {0, 0, 0});
    scene::Light top = point_light({0, 6, 0}, {1, 1, 1});
    top.projected_through = sphere({0.5, 3, 0}, 1, {});
    s.lights.push_back(top);
    scene::Light fill = point_light({-3, 4, -3}, glm::dvec3(0.3));
    fill.shadowless = true;
    fill.projected_through = sphere({-1.5, 2, -1.5}, 0.5, {});
    s.lights.push_back(fill);
    s.objects.push_back(plane({0, 1, 0}, 0, {rgb(1, 1, 1)}));
    s.objects.push_back(sphere({1, 0.5, 0}, 0.5, {rgb(1, 0.5, 0.2)}));
    expect_matches(s, "projthru.ppm", 0);
}

TEST(Tracer, IridescenceTintsDiffuseAndHighlights) {
    scene::Scene s = scene_37();
    s.globals.irid_wavelength = {0.6, 0.5, 0.35};
    s.camera.location = {0, 0, -5};
    s.lights.push_back(point_light({-3, 4, -6}, {1, 1, 1}));
    s.lights.push_back(point_light({4, 0, -2}, glm::dvec3(0.4)));
    Material pearl{rgb(0.8, 0.8, 0.8)};
    pearl.finish.phong = 0.6;
    pearl.finish.irid_amount = 0.4;
    pearl.finish.irid_thickness = 0.3;
    s.objects.push_back(sphere({-1.1, 0, 0}, 1, pearl));
    Material film{rgb(1, 1, 1)};
    film.finish.diffuse = 0.5;
    film.finish.irid_amount = 0.7;
    film.finish.irid_thickness = 0.8;
    s.objects.push_back(sphere({1.1, 0, 0}, 1, film));
    expect_matches(s, "irid.ppm", 0);
}

TEST(Tracer, UnsupportedFeatureIsAnError) {
    scene::Scene s = v1_scene(true);
    s.unsupported.push_back({"isosurface", {}});
    TestIntersector g(s);
    EXPECT_THROW(Tracer(s, g, TraceOptions{}), lumen::LumenError);
}

}  // namespace
}  // namespace lumen::render::test
