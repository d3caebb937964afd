// What the gathers that follow a solve see where they land: the direct light and the material
// at the hit itself, plus the solution's indirect light over the element (Solution::indirect);
// with many lights, one picked per hit and weighted so that the mean is the sum.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "interp/interpret.hpp"
#include "render/frame.hpp"
#include "render/radiosity/point_gather.hpp"
#include "render/radiosity/scene_mesh.hpp"
#include "render/radiosity/scene_solution.hpp"
#include "render/radiosity/surface_light.hpp"

namespace lumen::cli {
namespace {

namespace rad = render::radiosity;

scene::Scene parse(SourceManager& sources, const std::string& text) {
    return interp::interpret_text(sources, "hits.pov", text, {});
}

// A floor under a light, a ceiling above both, and a thin rod between light and floor whose
// shadow (x in (0.22, 0.38)) falls inside the floor's elements (1 unit): the corners of the
// elements under it are lit.
std::string rod_scene(int recursion_limit) {
    return "#version 3.7; global_settings { radiosity { recursion_limit " +
           std::to_string(recursion_limit) +
           " } }\n"
           "camera { location <0, 3, -4> look_at <0, 0, 0> }\n"
           "light_source { <0.3, 2.5, 0.3> rgb 1 }\n"
           "box { <-2, -0.1, -2>, <2, 0, 2> pigment { rgb 0.6 } finish { diffuse 1 } }\n"
           "box { <0.25, 1, -1.5>, <0.35, 1.1, 1.5> pigment { rgb 0.5 } }\n"
           "box { <-2, 3, -2>, <2, 3.1, 2> pigment { rgb 0.8 } finish { diffuse 1 } }\n";
}

rad::RadiosityOptions options() {
    rad::RadiosityOptions o;
    o.patch_size = 1.0;
    o.ff_rays = 16;
    return o;
}

// The floor straight down from (x, 1, z): the hit, its element and barycentric coordinates.
struct FloorHit {
    render::Hit hit;
    long element = -1;
    glm::dvec3 bary{0};
};

FloorHit floor_below(const render::RenderFrame& frame, const rad::SceneMesh& mesh, double x,
                     double z) {
    FloorHit f;
    const glm::dvec3 from(x, 0.5, z), down(0, -1, 0);
    EXPECT_TRUE(frame.geometry().intersect(render::Ray{from, down}, 1e-4, 1e9, f.hit));
    f.element = mesh.find(from, down, f.hit.t, 1e-4, f.hit.object, f.bary);
    EXPECT_GE(f.element, 0);
    return f;
}

glm::dvec3 interpolated(const rad::SceneMesh& mesh, const std::vector<glm::dvec3>& values,
                        const FloorHit& f) {
    const uint32_t side =
        rad::seen_side(mesh.elements[size_t(f.element)], f.hit.normal, glm::dvec3(0, 1, 0));
    return rad::interpolate_sides(mesh, values, f.element, f.bary, side);
}

// A gather landing in the rod's shadow sees the shadow; the element's B, interpolated from
// its lit corners, does not. Beside the shadow it sees ρ times the light's cosine term.
TEST(RadiosityGatherHits, AGatherSeesTheShadowWhereItLandsNotItsElementsCorners) {
    SourceManager sources;
    const scene::Scene s = parse(sources, rod_scene(1));
    const render::RenderFrame frame(s);
    const rad::SceneMesh mesh = rad::build_scene_mesh(frame.geometry(), 1.0);
    rad::SolveInfo info;
    const rad::Solution sol = rad::solve_scene(frame, mesh, options(), 2, info);
    rad::PointGatherSettings settings;
    settings.bounces = 1;
    const rad::PointGather points(frame, mesh, &sol.B, settings, &sol.indirect);
    ASSERT_TRUE(points.evaluates_every_hit());
    EXPECT_FALSE(points.uses_element(1)) << "one bounce: no indirect light to look up";

    const FloorHit shade = floor_below(frame, mesh, 0.3, 0.1);
    const FloorHit lit = floor_below(frame, mesh, 0.6, 0.1);
    const glm::dvec3 down(0, -1, 0);
    const glm::dvec3 in_shade = points.leaving(shade.hit, down, 1, shade.element, shade.bary);
    const glm::dvec3 in_light = points.leaving(lit.hit, down, 1, lit.element, lit.bary);
    const glm::dvec3 to_light = glm::dvec3(0.3, 2.5, 0.3) - lit.hit.point;
    EXPECT_NEAR(in_light.x, 0.6 * to_light.y / glm::length(to_light), 1e-6);
    EXPECT_LT(in_shade.x, 1e-12);
    // What a gather saw before: B over the element, lit at its corners.
    EXPECT_GT(interpolated(mesh, sol.B, shade).x, 0.3);
}

// The solution's indirect light is what B holds besides E + ρH: zeros for one bounce, the
// last gather for more (limit 0: solved to convergence by the dense solver), and the floor
// under the lit ceiling gets some.
TEST(RadiosityGatherHits, SolutionIndirectIsWhatBHoldsBesidesTheDirectLight) {
    SourceManager sources;
    for (int limit : {1, 2, 3, 0}) {
        const scene::Scene s = parse(sources, rod_scene(std::max(limit, 1)));
        const render::RenderFrame frame(s);
        const rad::SceneMesh mesh = rad::build_scene_mesh(frame.geometry(), 1.0);
        rad::SolveInfo info;
        rad::RadiosityOptions o = options();
        if (limit == 0) {
            o.bounces = 0;
            o.method = rad::Method::Matrix;
        }
        const rad::Solution sol = rad::solve_scene(frame, mesh, o, 2, info);
        const double tolerance = limit == 0 ? 1e-3 : 1e-9;  // the solve's own tolerance
        const std::vector<glm::dvec3> H = rad::direct_light(frame, mesh, 2);
        ASSERT_EQ(sol.indirect.size(), sol.B.size());
        double most = 0;
        for (size_t u = 0; u < sol.B.size(); ++u) {
            const rad::MeshVertex& v = mesh.vertices[u / 2];
            const glm::dvec3 expect = v.emission + v.rho * (H[u] + sol.indirect[u]);
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(sol.B[u][c], expect[c], tolerance) << u;
            most = std::max(most, sol.indirect[u].x);
        }
        if (limit == 1)
            EXPECT_EQ(most, 0.0);
        else
            EXPECT_GT(most, 0.01) << "recursion_limit " << limit;
    }
}

// With more lights than are traced one by one, one light per hit stands for all: its
// visibility weighted by the sum of the unshadowed terms over its own. Over u the mean is
// the sum that direct_light_at traces light by light, shadows included.
TEST(RadiosityGatherHits, OneLightPickedPerHitAveragesToEveryLight) {
    SourceManager sources;
    std::string text =
        "#version 3.7;\n"
        "camera { location <0, 3, -4> look_at <0, 0, 0> }\n"
        "box { <-2, -0.1, -2>, <2, 0, 2> pigment { rgb 1 } }\n"
        // Shadows the lights at x < 0 from the origin.
        "box { <-0.6, 0.5, -1>, <-0.4, 0.6, 1> pigment { rgb 1 } }\n";
    for (int i = 0; i < 6; ++i)
        text += "light_source { <" + std::to_string(-2.5 + i) + ", 1, 0.2> rgb <" +
                std::to_string(0.2 + 0.1 * i) + ", 0.5, " + std::to_string(1.0 - 0.15 * i) +
                "> }\n";
    text += "light_source { <0, 5, 0> rgb 0.3 shadowless }\n";
    const scene::Scene s = parse(sources, text);
    const render::RenderFrame frame(s);
    const glm::dvec3 p(0, 1e-6, 0), n(0, 1, 0);
    render::TraceCounters counters;
    const glm::dvec3 every = rad::direct_light_at(frame.lights(), frame.geometry(), p, n, 1,
                                                  counters);
    constexpr int kSteps = 20000;
    glm::dvec3 mean(0);
    double lowest = 1e30, highest = 0;
    for (int k = 0; k < kSteps; ++k) {
        const glm::dvec3 one = rad::direct_light_one_of(frame.lights(), frame.geometry(), p, n,
                                                        1, (k + 0.5) / kSteps, counters);
        mean += one / double(kSteps);
        lowest = std::min(lowest, one.x);
        highest = std::max(highest, one.x);
    }
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c], every[c], 1e-3 * every[c]) << c;
    EXPECT_LT(lowest, 0.9 * every.x) << "some picks are shadowed";
    EXPECT_GT(highest, every.x);
    EXPECT_GT(every.x, 0.3) << "the scene lights the point";
}

// A split element's midpoint finds the true surface under it with a probe as long as half
// its edge. On a thin shell (two sheets of one mesh, 0.1 apart) the probe from above meets
// the other sheet first; the gather must start on the sheet the point lies on
// (camera/mesh_camera/baking_demo.pov's vases: blocks of dark elements where midpoints
// gathered from the vase's far wall).
TEST(RadiosityGatherHits, AGatherStartsOnTheSurfaceNearestItsPoint) {
    SourceManager sources;
    const scene::Scene s = parse(sources,
                                 "#version 3.7;\n"
                                 "camera { location <0, 3, -4> look_at <0, 0, 0> }\n"
                                 "mesh { triangle { <-1, 0, -1>, <1, 0, -1>, <1, 0, 1> }\n"
                                 "       triangle { <-1, 0.1, -1>, <1, 0.1, -1>, <1, 0.1, 1> }\n"
                                 "       pigment { rgb 1 } }\n");
    const render::RenderFrame frame(s);
    render::Hit hit;
    ASSERT_TRUE(frame.geometry().intersect(render::Ray{{0.5, -1, -0.5}, {0, 1, 0}}, 1e-4, 1e9, hit));
    ASSERT_NEAR(hit.point.y, 0, 1e-9);
    for (double y : {0.0, -0.02, 0.02}) {  // on the lower sheet, and a chord's error off it
        glm::dvec3 p(0.5, y, -0.5), n(0, 1, 0);
        ASSERT_TRUE(rad::onto_surface(frame.geometry(), hit.object, p, n, 0.5));
        EXPECT_NEAR(p.y, 0, 1e-9) << "from y = " << y;
        EXPECT_NEAR(std::fabs(n.y), 1, 1e-9);
    }
}

}  // namespace
}  // namespace lumen::cli
