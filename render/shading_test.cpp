// Unit checks of the finish model and light attenuation formulas.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "render/geometry.hpp"
#include "render/lights.hpp"
#include "render/shading.hpp"
#include "render/shadows.hpp"

namespace lumen::render {
namespace {

TEST(Shading, MetallicFactorIsNeutralForWhiteAndTintsOtherwise) {
    const glm::dvec3 white = metallic_factor(1.0, 1.0, glm::dvec3(1));
    EXPECT_DOUBLE_EQ(white.x, 1.0);
    const glm::dvec3 red = metallic_factor(1.0, 1.0, {1, 0, 0});
    EXPECT_DOUBLE_EQ(red.x, 1.0);
    EXPECT_LT(red.y, 0.5);  // head-on: Fm small, highlight takes the pigment colour
    EXPECT_GT(metallic_factor(1.0, 0.01, {1, 0, 0}).y, red.y);  // grazing: whiter
}

TEST(Shading, ReflectionFalloffBlendsMinAndMax) {
    scene::Finish f;
    f.reflection_min = glm::dvec3(0.1);
    f.reflection_max = glm::dvec3(0.9);
    f.reflection_falloff = 2;
    EXPECT_DOUBLE_EQ(reflectivity(f, 1.0, 1.0, glm::dvec3(1)).colour.x, 0.1);  // head-on
    EXPECT_NEAR(reflectivity(f, 0.5, 1.0, glm::dvec3(1)).colour.x, 0.25 * 0.9 + 0.75 * 0.1, 1e-12);
    EXPECT_DOUBLE_EQ(reflectivity(f, 0.5, 1.0, glm::dvec3(1)).weight, 0.9);
}

TEST(Shading, FresnelReflectanceOfGlass) {
    scene::Finish f;
    f.reflection_max = glm::dvec3(1);
    f.fresnel = true;
    // Normal incidence on n = 1.5: ((n−1)/(n+1))² = 0.04.
    EXPECT_NEAR(reflectivity(f, 1.0, 1.5, glm::dvec3(1)).colour.x, 0.04, 1e-9);
    // Leaving glass beyond the critical angle: total reflection.
    EXPECT_DOUBLE_EQ(reflectivity(f, 0.3, 1 / 1.5, glm::dvec3(1)).colour.x, 1.0);
}

TEST(Shading, ReflectedRayStaysAboveTheSurface) {
    const glm::dvec3 d = glm::normalize(glm::dvec3(1, -1, 0));
    const glm::dvec3 r = reflect_direction(d, {0, 1, 0}, {0, 1, 0});
    EXPECT_NEAR(r.y, std::sqrt(0.5), 1e-12);
}

TEST(Shading, IridFactorFollowsPovFilmModel) {
    // Factors measured with povray 3.7 (16-bit linear output of a lit plane, diffuse only):
    // irid { 0.5 thickness 0.1 }, default irid_wavelength <0.70,0.52,0.48>.
    scene::Finish f;
    f.irid_amount = 0.5;
    f.irid_thickness = 0.1;
    const glm::dvec3 wl(0.70, 0.52, 0.48);
    const glm::dvec3 head_on = irid_factor(f, f.irid_thickness, wl, 1.0, -1.0);
    EXPECT_NEAR(head_on.x, 0.888748, 2e-4);
    EXPECT_NEAR(head_on.y, 0.625740, 2e-4);
    EXPECT_NEAR(head_on.z, 0.566964, 2e-4);
    // The view head-on.
    const glm::dvec3 light_at_60 = irid_factor(f, f.irid_thickness, wl, 0.5, -1.0);
    EXPECT_NEAR(light_at_60.x, 1.111224, 2e-4);
    EXPECT_NEAR(light_at_60.y, 0.880384, 2e-4);
    EXPECT_NEAR(light_at_60.z, 0.808608, 2e-4);
    // The eye and light angles enter symmetrically; no film means no change.
    const glm::dvec3 eye_at_60 = irid_factor(f, f.irid_thickness, wl, 1.0, 0.5);
    EXPECT_NEAR(eye_at_60.y, light_at_60.y, 1e-12);
    f.irid_thickness = 0;
    EXPECT_DOUBLE_EQ(irid_factor(f, f.irid_thickness, wl, 0.3, 0.7).z, 1.5);
}

TEST(Shading, IridTurbulenceVariesTheThicknessWithTheSceneGenerator) {
    scene::Finish f;
    f.irid_amount = 0.3;
    f.irid_thickness = 0.5;
    const glm::dvec3 p(1.3, -2.7, 0.37);
    EXPECT_EQ(irid_thickness(f, p, noise::Generator::RangeCorrected), 0.5);
    f.irid_turbulence = 0.6;
    scene::TurbulenceParams five;
    five.octaves = 5;
    for (noise::Generator g : {noise::Generator::Original, noise::Generator::Perlin}) {
        const double t = noise::turbulence(p, five, g);
        EXPECT_DOUBLE_EQ(irid_thickness(f, p, g), 0.5 * (1 + 0.6 * (2 * t - 1)));
    }
}

// A white surface point at the origin facing a light on -z, seen head-on, with finish `f`.
SurfaceSample facing_light(const scene::Finish& f) {
    SurfaceSample s;
    s.view = {0, 0, 1};
    s.normal = {0, 0, -1};
    s.colour = glm::dvec3(1);
    s.finish = &f;
    return s;
}

TEST(Shading, IridMultipliesTheLightForDiffuseAndHighlightsButNotAmbient) {
    scene::Light sl;
    sl.position = {0, 0, -10};
    const std::vector<LightSource> lights = prepare_lights({sl});
    LightingEnv env;
    env.lights = &lights;
    env.quality = 3;  // no shadow rays: no geometry needed
    scene::Finish f;
    f.ambient = glm::dvec3(0.2);
    f.diffuse = 0.25;
    f.phong = 0.3;
    f.irid_amount = 0.5;
    f.irid_thickness = 0.1;
    SurfaceSample s = facing_light(f);
    s.film_thickness = irid_thickness(f, s.point, env.noise_generator);  // as the tracer sets it
    ThreadState state;
    const glm::dvec3 lit = local_light(s, env, InteriorList{}, state);
    const glm::dvec3 k = irid_factor(f, f.irid_thickness, env.irid_wavelength, 1.0, 1.0);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(lit[c], 0.2 + (0.25 + 0.3) * k[c], 1e-12);
}

// A light straight ahead of facing_light()'s surface, in an empty scene for its shadow rays.
struct LightAhead {
    static std::vector<LightSource> light() {
        scene::Light sl;
        sl.position = {0, 0, -10};
        return prepare_lights({sl});
    }
    const std::vector<LightSource> lights = light();
    const Geometry geometry{std::vector<scene::ObjectPtr>{}};
    LightingEnv env;
    LightAhead() {
        env.lights = &lights;
        env.geometry = &geometry;
    }
};

// A surface lights cannot add to (no diffuse, no highlights: a media container's clear skin)
// sends no shadow rays; one with diffuse does. Each would walk through the container's media.
TEST(Shading, ASurfaceWithoutDiffuseOrHighlightsSendsNoShadowRays) {
    const LightAhead ahead;
    const LightingEnv& env = ahead.env;
    scene::Finish f;
    f.ambient = glm::dvec3(0);
    f.diffuse = 0;
    const SurfaceSample s = facing_light(f);
    ThreadState state;
    EXPECT_EQ(local_light(s, env, InteriorList{}, state), glm::dvec3(0));
    EXPECT_EQ(state.counters.shadow_rays, 0u);
    f.diffuse = 0.5;
    EXPECT_NEAR(local_light(s, env, InteriorList{}, state).x, 0.5, 1e-12);
    EXPECT_EQ(state.counters.shadow_rays, 1u);
}

// A black surface without highlights (a mirror's) sends none either: its diffuse light is
// black whatever the shadow. With a highlight, a colour or crand (which draws a number for
// each light that reaches it) it does.
TEST(Shading, ABlackSurfaceWithoutHighlightsSendsNoShadowRays) {
    const LightAhead ahead;
    const LightingEnv& env = ahead.env;
    scene::Finish f;
    f.ambient = glm::dvec3(0.1);
    f.diffuse = 0.6;
    SurfaceSample s = facing_light(f);
    s.colour = glm::dvec3(0);
    ThreadState state;
    EXPECT_EQ(local_light(s, env, InteriorList{}, state), glm::dvec3(0));
    EXPECT_EQ(state.counters.shadow_rays, 0u);
    s.colour = {0, 0, 0.5};
    EXPECT_NEAR(local_light(s, env, InteriorList{}, state).z, 0.05 + 0.3, 1e-12);
    EXPECT_EQ(state.counters.shadow_rays, 1u);
    s.colour = glm::dvec3(0);
    f.phong = 1;
    EXPECT_NEAR(local_light(s, env, InteriorList{}, state).x, 1, 1e-12);  // the highlight's peak
    EXPECT_EQ(state.counters.shadow_rays, 2u);
    f.phong = 0;
    f.crand = 0.2;
    ThreadState reference = state;
    local_light(s, env, InteriorList{}, state);
    EXPECT_EQ(state.counters.shadow_rays, 3u);
    reference.uniform();  // the one draw crand made
    EXPECT_EQ(state.uniform(), reference.uniform());
}

TEST(Lights, ProjectedThroughPassesOnlyAlongSegmentsCrossingTheObject) {
    scene::Light l;
    l.position = {0, 10, 0};
    auto ball = std::make_shared<scene::Object>();
    ball->shape = scene::Sphere{{0, 5, 0}, 1};
    l.projected_through = ball;
    const auto p = prepare_lights({l});
    const glm::dvec3 up(0, 1, 0);
    // Shadows are tested up to the object's nearest crossing (its bottom, y = 4), no further.
    EXPECT_NEAR(projection_reach(p[0], {0, 0, 0}, up, 10).value(), 4, 1e-12);
    EXPECT_FALSE(projection_reach(p[0], {3, 0, 0}, glm::normalize(glm::dvec3(-3, 10, 0)),
                                  std::sqrt(109.0)));
    // The object must lie between the point and the light, not beyond the light.
    EXPECT_FALSE(projection_reach(p[0], {0, 0, 0}, up, 3));
    // Without a projection the whole way is tested, even a parallel light's negative one.
    EXPECT_EQ(projection_reach(prepare_lights({scene::Light{}})[0], {0, 0, 0}, up, 1), 1.0);
    EXPECT_EQ(projection_reach(prepare_lights({scene::Light{}})[0], {0, 0, 0}, up, -2), -2.0);
}

TEST(Lights, FadeIsTwoAtTheLightAndOneAtFadeDistance) {
    scene::Light l;
    l.position = {0, 0, 0};
    l.fade_distance = 3;
    l.fade_power = 2;
    const auto prepared = prepare_lights({l});
    LightSample s;
    ASSERT_TRUE(illuminate(prepared[0], {3, 0, 0}, s));
    EXPECT_NEAR(s.colour.x, 1.0, 1e-12);
    EXPECT_NEAR(s.dir.x, -1, 1e-12);
    EXPECT_NEAR(s.distance, 3, 1e-12);
    ASSERT_TRUE(illuminate(prepared[0], {1e-6, 0, 0}, s));
    EXPECT_NEAR(s.colour.x, 2.0, 1e-6);
}

TEST(Lights, SpotlightConeAndParallelDirection) {
    scene::Light spot;
    spot.type = scene::LightType::Spot;
    spot.position = {0, 10, 0};
    spot.point_at = {0, 0, 0};
    spot.radius = 10;
    spot.falloff = 20;
    const auto lights = prepare_lights({spot});
    LightSample s;
    ASSERT_TRUE(illuminate(lights[0], {0, 0, 0}, s));
    EXPECT_DOUBLE_EQ(s.colour.x, 1.0);
    EXPECT_FALSE(illuminate(lights[0], {10, 0, 0}, s));  // 45° is outside the falloff
    ASSERT_TRUE(illuminate(lights[0], {10 * std::tan(15 * M_PI / 180), 0, 0}, s));
    EXPECT_GT(s.colour.x, 0.0);
    EXPECT_LT(s.colour.x, 1.0);

    scene::Light sun;
    sun.parallel = true;
    sun.position = {0, 10, 0};
    sun.point_at = {0, 0, 0};
    const auto p = prepare_lights({sun});
    ASSERT_TRUE(illuminate(p[0], {5, 0, 3}, s));
    EXPECT_NEAR(s.dir.y, 1, 1e-12);
    EXPECT_NEAR(s.distance, 10, 1e-12);
}

TEST(Lights, AreaGridSpansTheWholeAxes) {
    scene::Light l;
    l.area = scene::AreaLight{{2, 0, 0}, {0, 0, 4}, 3, 5};
    const auto p = prepare_lights({l});
    const glm::dvec3 corner = area_sample_position(p[0], 0, 0, {0, 1, 0});
    EXPECT_NEAR(corner.x, -1, 1e-12);
    EXPECT_NEAR(corner.z, -2, 1e-12);
    const glm::dvec3 last = area_sample_position(p[0], 2, 4, {0, 1, 0});
    EXPECT_NEAR(last.x, 1, 1e-12);
    EXPECT_NEAR(last.z, 2, 1e-12);
}

// `orient` turns the grid to face the point, both axes |axis1| long: made once per point
// (area_axes) for all of its samples.
TEST(Lights, OrientedAxesFaceThePoint) {
    scene::Light l;
    l.area = scene::AreaLight{{2, 0, 0}, {0, 0, 4}, 3, 5};
    l.area->orient = true;
    const auto p = prepare_lights({l});
    const glm::dvec3 to_light = glm::normalize(glm::dvec3(1, 1, 0.5));
    const AreaAxes axes = area_axes(p[0], to_light);
    EXPECT_NEAR(glm::dot(axes.axis1, to_light), 0, 1e-12);
    EXPECT_NEAR(glm::dot(axes.axis2, to_light), 0, 1e-12);
    EXPECT_NEAR(glm::dot(axes.axis1, axes.axis2), 0, 1e-12);
    EXPECT_NEAR(glm::length(axes.axis2), 2, 1e-12);
    const glm::dvec3 far = area_sample_position(p[0], 2, 4, to_light);
    EXPECT_EQ(far, area_sample_position(p[0], axes, 2, 4));
    EXPECT_NEAR(glm::dot(far - p[0].position, to_light), 0, 1e-12);
    EXPECT_GT(glm::distance(far, p[0].position), 0.5);
}

TEST(Shadows, InteriorFadeFormula) {
    scene::Interior in;
    in.fade_distance = 1;
    in.fade_power = 2;
    in.fade_colour = {0.5, 0.2, 0.2};
    const glm::dvec3 a = interior_fade(in, 1.0, true);
    EXPECT_NEAR(a.x, 0.5 + 0.5 / 2, 1e-12);
    EXPECT_NEAR(a.y, 0.2 + 0.8 / 2, 1e-12);
    in.fade_power = 0;
    EXPECT_DOUBLE_EQ(interior_fade(in, 1.0, true).x, 1.0);  // shadow rays need fade_power > 0
    EXPECT_LT(interior_fade(in, 1.0, false).x, 1.0);       // eye rays do not
}

}  // namespace
}  // namespace lumen::render
