// Every surface of a radiosity scene gets indirect light: curved shapes (whose elements are
// chords inside them), CSG the mesher does not cut, and, under #version < 3.7, ambient acting
// as emission as POV-Ray 3.7 lets it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cli/radiosity_pass.hpp"
#include "interp/interpret.hpp"
#include "render/frame.hpp"
#include "render/radiosity/surface_light.hpp"

namespace lumen::cli {
namespace {

namespace rad = render::radiosity;

scene::Scene parse(SourceManager& sources, const std::string& text) {
    return interp::interpret_text(sources, "surfaces.pov", text, {});
}

render::RenderOptions view() {
    render::RenderOptions r;
    r.width = 80;
    r.height = 60;
    r.threads = 2;
    return r;
}

// Mean red of the incident light over the hits of rays from `from` towards `targets`, with
// the pass's display `mode`.
double mean_incident(const scene::Scene& s, rad::DisplayMode mode, const glm::dvec3& from,
                     const std::vector<glm::dvec3>& targets, int& hits) {
    RadiosityPass pass;
    std::vector<std::string> log;
    rad::RadiosityOptions o;
    o.display = mode;
    const render::IndirectLight* light = pass.prepare(s, o, view(), log);
    EXPECT_NE(light, nullptr);
    if (!light) return 0;
    render::Geometry geometry(s);
    render::ThreadState state;
    double sum = 0;
    hits = 0;
    for (const glm::dvec3& t : targets) {
        const glm::dvec3 d = glm::normalize(t - from);
        render::Hit hit;
        if (!geometry.intersect(render::Ray{from, d}, 1e-4, 1e9, hit)) continue;
        glm::dvec3 n = hit.normal;
        if (glm::dot(n, d) > 0) n = -n;
        const glm::dvec3 g = light->incident(hit, n, state);
        EXPECT_TRUE(std::isfinite(g.x + g.y + g.z));
        sum += g.x;
        ++hits;
    }
    return hits ? sum / hits : 0;
}

// Points along a ring about the y axis at height y.
std::vector<glm::dvec3> ring(double radius, double y, int n) {
    std::vector<glm::dvec3> p;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * M_PI * i / n;
        p.push_back({radius * std::cos(a), y, radius * std::sin(a)});
    }
    return p;
}

// `objects` in a sky (an emitting sphere) over a sunlit ground, seen by a camera at `camera`.
scene::Scene in_the_sky(SourceManager& sources, const std::string& camera,
                        const std::string& objects) {
    return parse(sources,
                 "#version 3.7; global_settings { radiosity { count 100 recursion_limit 1 } }\n"
                 "camera { location " + camera + " look_at 0 }\n"
                 "light_source { <-1.5, 1, -0.5>*10000 rgb 1 }\n"
                 "sphere { 0, 1 pigment { rgb <0.6, 0.7, 1> } finish { diffuse 0 emission 1 }\n"
                 "         hollow no_shadow scale 30000 }\n"
                 "plane { y, 0 pigment { rgb 0.8 } finish { diffuse 0.65 } }\n" + objects);
}

// radiosity2.pov's torus: a thin tube of few elements around, in a sky over a lit ground.
// The preview's vertex gathers start on the true surface: from the chords' midpoints they
// started inside the tube and saw its inside (black where the sun does not reach).
TEST(RadiositySurfaces, ACurvedShapeInShadowIsLitAsByPerPixelGathers) {
    SourceManager sources;
    const scene::Scene s = in_the_sky(
        sources, "<3.8, 7.8, -10>",
        "torus { 5.2, 0.5 translate 0.5*y pigment { rgb 1 } finish { diffuse 0.65 } }\n");
    // The tube at its own height as the camera sees it, its far half from inside the ring,
    // partly in the tube's own shadow.
    const std::vector<glm::dvec3> targets = ring(5.2, 0.5, 24);
    int preview_hits = 0, gather_hits = 0;
    const glm::dvec3 eye(3.8, 7.8, -10);
    const double preview =
        mean_incident(s, rad::DisplayMode::Preview, eye, targets, preview_hits);
    const double gather = mean_incident(s, rad::DisplayMode::Gather, eye, targets, gather_hits);
    ASSERT_EQ(preview_hits, 24);
    ASSERT_EQ(gather_hits, 24);
    EXPECT_GT(gather, 0.3);
    EXPECT_NEAR(preview / gather, 1.0, 0.15);
}

// A difference is not meshed: its surface gets a per-point gather, the sky's light.
TEST(RadiositySurfaces, CsgTheMesherDoesNotCutGetsIndirectLight) {
    SourceManager sources;
    const scene::Scene s =
        in_the_sky(sources, "<0, 3, -6>",
                   "difference { sphere { <0, 1, 0>, 1 } box { <0, 1, -2>, <2, 3, 0> }\n"
                   "             pigment { rgb 1 } finish { diffuse 0.65 } }\n");
    // Its shadowed side (away from the light at -x, -z): these points see at least a quarter
    // of the sky hemisphere, red 0.6 (0 when such surfaces got no indirect light).
    const std::vector<glm::dvec3> targets = {{0.7, 0.8, 0.7}, {0.9, 0.5, 0.3}, {0.3, 0.5, 0.9}};
    int hits = 0;
    const double g = mean_incident(s, rad::DisplayMode::Preview, {4, 1, 4}, targets, hits);
    ASSERT_EQ(hits, 3);
    EXPECT_GT(g, 0.6 / 4);
}

// The vertex gathers that land on unmeshed surfaces gather again there, through caches of
// their worker's own: two passes over the same scene with two threads give the same light.
TEST(RadiositySurfaces, GathersThroughUnmeshedSurfacesAreTheSameRunToRun) {
    SourceManager sources;
    std::string objects;
    for (int i = 0; i < 5; ++i)
        for (int k = 0; k < 5; ++k)
            objects += "difference { sphere { <" + std::to_string(2 * i - 4) + ", 0.6, " +
                       std::to_string(2 * k - 4) + ">, 0.7 } box { <-9, 0.9, -9>, <9, 2, 9> }\n"
                       "  pigment { rgb 1 } finish { diffuse 0.65 } }\n";
    scene::Scene s = in_the_sky(sources, "<0, 9, -9>", objects);
    s.globals.radiosity->recursion_limit = 2;
    const std::vector<glm::dvec3> ground = ring(3, 0, 40);
    int hits = 0;
    const double first = mean_incident(s, rad::DisplayMode::Preview, {0, 9, -9}, ground, hits);
    for (int run = 0; run < 3; ++run)
        EXPECT_EQ(mean_incident(s, rad::DisplayMode::Preview, {0, 9, -9}, ground, hits), first);
    EXPECT_EQ(hits, 40);
    EXPECT_GT(first, 0.1);
}

// POV-Ray 3.7 under #version 3.6: a surface's ambient is emission for radiosity (a plane of
// ambient 0.2 under a sky of ambient 1 rendered 0.2 + 0.5 × sky); from 3.7 on it is not.
TEST(RadiositySurfaces, AmbientIsEmissionOnlyBeforeVersion37) {
    SourceManager sources;
    auto scene_at = [&](const char* version) {
        return parse(sources, std::string("#version ") + version +
                                  "; global_settings { ambient_light 0.5 radiosity { } }\n"
                                  "camera { location <0, 1, -3> look_at <0, 1, 0> }\n"
                                  "box { <-2, -0.1, -2>, <2, 0, 2> pigment { rgb 1 }\n"
                                  "      finish { ambient 1 diffuse 0 } }\n"
                                  "box { <-2, 2, -2>, <2, 2.1, 2> pigment { rgb 1 } }\n");
    };
    const scene::Scene old_scene = scene_at("3.6"), new_scene = scene_at("3.7");
    EXPECT_EQ(rad::ambient_emission(old_scene), glm::dvec3(0.5));
    EXPECT_EQ(rad::ambient_emission(new_scene), glm::dvec3(0));
    const std::vector<glm::dvec3> ceiling = {{0, 2, 0}, {0.5, 2, 0.5}, {-0.5, 2, -0.5}};
    int hits = 0;
    // The ceiling's underside sees the glowing floor (ambient 1 × ambient_light 0.5) only
    // under 3.6; no light source anywhere.
    const double lit =
        mean_incident(old_scene, rad::DisplayMode::Preview, {0, 1, 0}, ceiling, hits);
    EXPECT_EQ(hits, 3);
    EXPECT_GT(lit, 0.2);
    const double dark =
        mean_incident(new_scene, rad::DisplayMode::Preview, {0, 1, 0}, ceiling, hits);
    EXPECT_EQ(hits, 3);
    EXPECT_LT(dark, 1e-9);
}

}  // namespace
}  // namespace lumen::cli
