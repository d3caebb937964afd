// Media integration against POV-Ray's closed forms (constant media, method 3: emission a
// left Riemann sum over N·sc steps that leaves each interval's last step out, transmittance
// exactly exp(-sigma_t L)), the phase functions, and shadow rays through containers. Whole
// renders are compared with POV-Ray's in tests/media/media.pov.
#include <cmath>

#include <gtest/gtest.h>

#include "render/geometry.hpp"
#include "render/media.hpp"
#include "render/shadows.hpp"

namespace lumen::render {
namespace {

scene::Media emitting(double emission, double absorption) {
    scene::Media m;
    m.emission = glm::dvec3(emission);
    m.absorption = glm::dvec3(absorption);
    return m;
}

MediaEffect along(const std::vector<const scene::Media*>& media, double depth) {
    LightingEnv env;
    InteriorList none;
    ThreadState state;
    return integrate_media(media, Ray{glm::dvec3(0), glm::dvec3(0, 0, 1)}, depth, true, env, none,
                           state);
}

// Te = eps h sum_{m=0}^{N sc - 1} exp(-sigma h m) with h = L / (N sc): POV-Ray's own figures
// for L = 2, sigma_t = 1, eps = 1 are 1.0168 (samples 10) and 1.3679 (samples 1).
double closed_form(double length, double sigma, double eps, int intervals, int samples) {
    const int sc = std::max(2, samples / 2 + 1);
    const double h = length / (intervals * sc);
    double sum = 0;
    for (int m = 0; m < intervals * sc; ++m) sum += std::exp(-sigma * h * m);
    return eps * h * sum;
}

TEST(Media, ConstantMediaMatchPovRaysClosedForm) {
    scene::Media m = emitting(1, 1);
    const MediaEffect e = along({&m}, 2);
    EXPECT_NEAR(e.added.x, 1.0168, 1e-4);
    EXPECT_NEAR(e.added.x, closed_form(2, 1, 1, 1, 10), 1e-12);
    EXPECT_NEAR(e.transmittance.y, std::exp(-2.0), 1e-12);
    m.samples_min = m.samples_max = 1;
    EXPECT_NEAR(along({&m}, 2).added.z, 1.3679, 1e-4);
    m.intervals = 3;  // an unlit constant segment takes one interval whatever is asked
    EXPECT_NEAR(along({&m}, 2).added.z, 1.3679, 1e-4);
}

TEST(Media, DensityMakesTheMediaVaryAndIntervalsCount) {
    scene::Media m = emitting(1, 1);
    auto density = std::make_shared<scene::Pigment>();
    density->pattern.kind = scene::pattern::Gradient{{0, 0, 1}};  // 0 at the start, up along z
    m.densities.push_back(density);
    m.intervals = 4;
    const MediaEffect e = along({&m}, 0.9);
    // Less than the constant media's emission, and more light left through.
    scene::Media constant = emitting(1, 1);
    constant.intervals = 4;
    const MediaEffect c = along({&constant}, 0.9);
    EXPECT_LT(e.added.x, c.added.x);
    EXPECT_GT(e.transmittance.x, c.transmittance.x);
    EXPECT_NEAR(e.transmittance.x, std::exp(-0.9 * 0.9 / 2), 0.05);  // the integral of z over 0.9
}

TEST(Media, SeveralMediaAddAndTheFirstWithMostIntervalsLeads) {
    scene::Media a = emitting(0.5, 0.2), b = emitting(0.25, 0.3);
    const MediaEffect both = along({&a, &b}, 1.5);
    EXPECT_NEAR(both.transmittance.x, std::exp(-0.5 * 1.5), 1e-12);
    EXPECT_NEAR(both.added.x, closed_form(1.5, 0.5, 0.75, 1, 10), 1e-12);
}

TEST(Media, EscapingRaysSaturateButStayFinite) {
    // POV-Ray: emission 1e-12 adds exactly 0.02, absorption 1e-11 multiplies by e^-0.2.
    scene::Media glow = emitting(1e-12, 0), dark = emitting(0, 1e-11);
    EXPECT_NEAR(along({&glow}, kMediaEscapeDepth).added.x, 0.02, 1e-12);
    EXPECT_NEAR(along({&dark}, kMediaEscapeDepth).transmittance.x, std::exp(-0.2), 1e-9);
    scene::Media strong = emitting(1e300, 0);
    const MediaEffect s = along({&strong}, kMediaEscapeDepth);
    EXPECT_TRUE(std::isfinite(s.added.x));
    EXPECT_TRUE(std::isfinite(s.transmittance.x));
}

TEST(Media, PhaseFunctionsArePovRays) {
    scene::Media m;
    EXPECT_DOUBLE_EQ(phase(m, 0.3), 1);
    m.scattering_type = 4;  // Rayleigh
    EXPECT_DOUBLE_EQ(phase(m, 1), 0.799372013 * 2);
    m.scattering_type = 2;  // Mie hazy, forward
    EXPECT_DOUBLE_EQ(phase(m, 1), 0.576655375 * 10);
    m.scattering_type = 5;
    m.eccentricity = 0.6;
    EXPECT_NEAR(phase(m, 1), (1 - 0.36) / std::pow(1 + 0.36 - 1.2, 1.5), 1e-12);
    EXPECT_NEAR(phase(m, -1), (1 - 0.36) / std::pow(1 + 0.36 + 1.2, 1.5), 1e-12);
}

// A clear sphere of media between a point and the light dims the light by exp(-sigma chord),
// and a ray starting inside it by the way out only; the stretch from the last surface to the
// light is left undimmed, as POV-Ray leaves it.
TEST(Media, ShadowRaysLoseLightInContainers) {
    auto media = std::make_shared<scene::Media>();
    media->absorption = glm::dvec3(0.5);
    auto clear = std::make_shared<scene::Texture>();
    auto pigment = std::make_shared<scene::Pigment>();
    pigment->colour = {1, 1, 1, 0, 1};
    clear->pigment = pigment;
    auto sphere = std::make_shared<scene::Object>();
    sphere->shape = scene::Sphere{glm::dvec3(0), 1};
    sphere->texture = {clear};
    sphere->interior = scene::Interior{};
    sphere->interior->media.push_back(media);
    sphere->hollow = true;
    const Geometry g(std::vector<scene::ObjectPtr>{sphere});
    TraceCounters counters;
    const glm::dvec3 through =
        shadow_filter(g, glm::dvec3(0, 0, -3), glm::dvec3(0, 0, 1), 6, InteriorList{}, counters);
    EXPECT_NEAR(through.x, std::exp(-0.5 * 2), 1e-9);
    InteriorList inside;
    inside.push(&*sphere->interior, &*sphere->interior, true);
    const glm::dvec3 out =
        shadow_filter(g, glm::dvec3(0, 0, 0.25), glm::dvec3(0, 0, 1), 6, inside, counters);
    EXPECT_NEAR(out.x, std::exp(-0.5 * 0.75), 1e-9);
    const glm::dvec3 to_inside =
        shadow_filter(g, glm::dvec3(0, 0, -3), glm::dvec3(0, 0, 1), 2.5, InteriorList{}, counters);
    EXPECT_DOUBLE_EQ(to_inside.x, 1);
}

// A shadow ray leaving a container samples the stretch as that container's media says, even
// inside another container with more intervals: a gradient-density sphere (intervals 1) inside
// a constant fog sphere (intervals 4): the rule of render/shadows.cpp (closer to POV-Ray than the
// most-intervals lead, not yet all of its rule).
TEST(Media, ShadowRayLeavingAContainerSamplesAsItsMedia) {
    auto clear = std::make_shared<scene::Texture>();
    auto pigment = std::make_shared<scene::Pigment>();
    pigment->colour = {1, 1, 1, 0, 1};
    clear->pigment = pigment;
    auto container = [&](double radius, std::shared_ptr<scene::Media> media) {
        auto o = std::make_shared<scene::Object>();
        o->shape = scene::Sphere{glm::dvec3(0), radius};
        o->texture = {clear};
        o->interior = scene::Interior{};
        o->interior->media.push_back(media);
        o->hollow = true;
        return o;
    };
    auto fog = std::make_shared<scene::Media>();
    fog->absorption = glm::dvec3(0.2);
    fog->intervals = 4;
    auto inner = std::make_shared<scene::Media>();
    inner->absorption = glm::dvec3(1.5);
    auto density = std::make_shared<scene::Pigment>();
    density->pattern.kind = scene::pattern::Gradient{{0, 0, 1}};
    inner->densities.push_back(density);
    const auto outer_sphere = container(2, fog), inner_sphere = container(1, inner);
    const Geometry g(std::vector<scene::ObjectPtr>{outer_sphere, inner_sphere});
    InteriorList in_fog;
    in_fog.push(&*outer_sphere->interior, &*outer_sphere->interior, true);
    TraceCounters counters;
    const glm::dvec3 got =
        shadow_filter(g, glm::dvec3(0, 0, -1.5), glm::dvec3(0, 0, 1), 10, in_fog, counters);
    // Fog to the inner sphere, both media through it led by the inner one, fog to the outside.
    const std::vector<const scene::Media*> both = {fog.get(), inner.get()};
    const Ray through{glm::dvec3(0, 0, -1), glm::dvec3(0, 0, 1)};
    const double fog_alone = std::exp(-0.2 * 0.5) * std::exp(-0.2 * 1);
    const glm::dvec3 led = media_transmittance(both, through, 2, inner.get());
    EXPECT_NEAR(got.x, fog_alone * led.x, 1e-12);
    // The fog's four intervals sample the gradient differently: the lead is what decides.
    const glm::dvec3 fog_led = media_transmittance(both, through, 2);
    EXPECT_GT(std::fabs(led.x - fog_led.x), 1e-4);
}

}  // namespace
}  // namespace lumen::render
