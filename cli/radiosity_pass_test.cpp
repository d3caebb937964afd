// The radiosity pass: Radiosity=on/off, the patch solution computed once and reused while
// only the camera moves, save/load of the solution, and no NaN in the indirect light.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "cli/radiosity_pass.hpp"
#include "interp/interpret.hpp"
#include "base/diagnostics.hpp"
#include "render/frame.hpp"
#include "render/radiosity/scene_mesh.hpp"
#include "render/radiosity/scene_solution.hpp"
#include "render/radiosity/solution_io.hpp"
#include "render/radiosity/solution_key.hpp"

namespace lumen::cli {
namespace {

// A lit floor under a ceiling: the ceiling gets no direct light, only indirect.
std::string room(double camera_z, double floor_colour = 0.8, const char* block = "radiosity { recursion_limit 2 }") {
    return "#version 3.7; global_settings { " + std::string(block) +
           " }\n"
           "camera { location <0, 1, " + std::to_string(camera_z) + "> look_at <0, 1, 0> }\n"
           "light_source { <0, 1.5, 0> rgb 1 }\n"
           "box { <-2, -0.1, -2>, <2, 0, 2> pigment { rgb " + std::to_string(floor_colour) +
           " } finish { diffuse 1 } }\n"
           "box { <-2, 2, -2>, <2, 2.1, 2> pigment { rgb 1 } finish { diffuse 0.5 } }\n";
}

scene::Scene parse(SourceManager& sources, const std::string& text) {
    return interp::interpret_text(sources, "room.pov", text, {});
}

render::radiosity::RadiosityOptions small() {
    render::radiosity::RadiosityOptions o;
    o.patch_size = 1.0;
    o.ff_rays = 16;
    o.display = render::radiosity::DisplayMode::Preview;
    return o;
}

// The reuse key of a scene's solution under `o`, as the pass computes it.
uint64_t key_of(const scene::Scene& s, const render::radiosity::RadiosityOptions& o = small()) {
    const render::RenderFrame frame(s);
    const auto mesh = render::radiosity::build_scene_mesh(frame.geometry(), o.patch_size, {},
                                                          &s.camera.location);
    return render::radiosity::solution_key(frame, mesh, o);
}

render::RenderOptions view() {
    render::RenderOptions r;
    r.width = 40;
    r.height = 30;
    r.threads = 2;
    return r;
}

TEST(RadiosityPass, SwitchForcesOnOrOff) {
    SourceManager sources;
    scene::Scene s = parse(sources, room(-5, 0.8, "assumed_gamma 1"));
    EXPECT_FALSE(s.globals.radiosity);
    render::radiosity::RadiosityOptions o;
    o.enabled = true;
    apply_radiosity_switch(s, o);
    ASSERT_TRUE(s.globals.radiosity);
    EXPECT_EQ(s.globals.radiosity->count, 35);  // POV's defaults
    o.enabled = false;
    apply_radiosity_switch(s, o);
    EXPECT_FALSE(s.globals.radiosity);
    RadiosityPass pass;
    std::vector<std::string> log;
    EXPECT_EQ(pass.prepare(s, o, view(), log), nullptr);  // nothing is meshed
}

TEST(RadiosityPass, ReusesTheSolutionWhenOnlyTheCameraMoves) {
    SourceManager sources;
    RadiosityPass pass;
    std::vector<std::string> log;
    const scene::Scene a = parse(sources, room(-5));
    ASSERT_NE(pass.prepare(a, small(), view(), log), nullptr);
    EXPECT_FALSE(pass.reused());
    const auto first = pass.solution()->G;
    const scene::Scene b = parse(sources, room(-6));  // camera moved
    EXPECT_EQ(key_of(a), key_of(b));
    ASSERT_NE(pass.prepare(b, small(), view(), log), nullptr);
    EXPECT_TRUE(pass.reused());
    EXPECT_EQ(pass.solution()->G, first);
    const scene::Scene c = parse(sources, room(-6, 0.5));  // the floor changed
    EXPECT_NE(key_of(b), key_of(c));
    ASSERT_NE(pass.prepare(c, small(), view(), log), nullptr);
    EXPECT_FALSE(pass.reused());
}

// The key follows what the solution depends on: the camera, highlights and the display
// options leave it alone; lights, the sky, an occluder the mesher skips, a pigment's filter
// and the solver's options change it.
TEST(RadiosityPass, ReuseKeyFollowsWhatTheSolutionDependsOn) {
    SourceManager sources;
    const std::string base = room(-5);
    const uint64_t key = key_of(parse(sources, base));
    auto with = [&](const std::string& extra) { return key_of(parse(sources, base + extra)); };
    auto replaced = [&](const std::string& from, const std::string& to) {
        std::string text = base;
        text.replace(text.find(from), from.size(), to);
        return key_of(parse(sources, text));
    };
    EXPECT_EQ(key_of(parse(sources, room(-7))), key);
    EXPECT_EQ(replaced("finish { diffuse 1 }", "finish { diffuse 1 phong 0.9 reflection 0.3 }"),
              key);
    auto display = small();
    display.display = render::radiosity::DisplayMode::Gather;
    display.gather_rays = 400;
    EXPECT_EQ(key_of(parse(sources, base), display), key);

    EXPECT_NE(replaced("light_source { <0, 1.5, 0> rgb 1 }", "light_source { <0, 1.5, 0> rgb 0.9 }"),
              key);
    EXPECT_NE(with("background { rgb <0, 0, 0.2> }\n"), key);
    EXPECT_NE(with("sky_sphere { pigment { rgb 0.3 } }\n"), key);
    const std::string blocker =
        "intersection { sphere { <0, 1, 0>, 0.3 } box { -1, 1 } pigment { rgb 1 } }\n";
    const uint64_t blocked = with(blocker);
    EXPECT_NE(blocked, key);  // not meshed (a CSG other than union), but it casts shadows
    EXPECT_NE(with("intersection { sphere { <0, 1.2, 0>, 0.3 } box { -1, 1 } pigment { rgb 1 } }\n"),
              blocked);
    EXPECT_NE(with("intersection { sphere { <0, 1, 0>, 0.3 } box { -1, 1 } "
                   "pigment { rgbf <1, 1, 1, 0.5> } }\n"),
              blocked);
    auto rays = small();
    rays.ff_rays = 32;
    EXPECT_NE(key_of(parse(sources, base), rays), key);
}

// The mesher meshes what the tracer compiled: a union's members with the union's transform
// and texture, and a light's looks_like object.
TEST(RadiosityPass, MeshesTheCompiledObjects) {
    SourceManager sources;
    const auto elements = [&](const std::string& extra) {
        const scene::Scene s = parse(sources, room(-5) + extra);
        const render::RenderFrame frame(s);
        return render::radiosity::build_scene_mesh(frame.geometry(), 1.0).elements;
    };
    const size_t bare = elements("").size();
    const std::string boxed =
        "union { box { <0, 0, 0>, <0.5, 0.5, 0.5> } translate <0, 0.5, 0> pigment { rgb 1 } }\n";
    EXPECT_GT(elements(boxed).size(), bare);
    const scene::Scene s = parse(sources, room(-5) + boxed);
    const render::RenderFrame frame(s);
    const auto mesh = render::radiosity::build_scene_mesh(frame.geometry(), 1.0);
    double highest = -1e9;  // below the ceiling, over the box: the floor (0) or the box
    for (const auto& v : mesh.vertices)
        if (v.position.x > -1e-6 && v.position.x < 0.5 + 1e-6 && v.position.y < 1.9)
            highest = std::max(highest, v.position.y);
    EXPECT_NEAR(highest, 1.0, 1e-9);  // the union's translate reached the box
    EXPECT_GT(elements("light_source { <1, 1, 1> rgb 1 looks_like { sphere { 0, 0.2 "
                       "pigment { rgb 1 } } } }\n")
                  .size(),
              bare);
}

// The sides of vertices that face into their own opaque solid, seen from outside it, are
// sealed (no form factors, no gather): only those.
TEST(RadiosityPass, SealsOnlyTheSidesInsideOpaqueSolids) {
    SourceManager sources;
    const std::string glass = "box { <1, 0.5, 1>, <1.5, 1, 1.5> pigment { rgbf 0.5 } }\n";
    const scene::Scene s = parse(sources, room(-5) + glass);
    const render::RenderFrame frame(s);
    auto top_of_floor = [](const render::radiosity::MeshVertex& v) {
        return std::fabs(v.position.y) < 1e-9 && std::fabs(v.position.x) < 0.9 &&
               std::fabs(v.position.z) < 0.9 && std::fabs(std::fabs(v.normal.y) - 1) < 1e-9;
    };
    const glm::dvec3 outside(0, 1, -5), in_floor(0, -0.05, 0);
    const auto seen = render::radiosity::build_scene_mesh(frame.geometry(), 0.5, {}, &outside);
    int floor_tops = 0;
    for (const auto& v : seen.vertices) {
        if (top_of_floor(v)) {
            ++floor_tops;
            ASSERT_TRUE(v.sealed == 1 || v.sealed == 2);
            const int open = v.sealed == 1 ? 1 : 0;  // the side left open faces up
            EXPECT_GT(open ? -v.normal.y : v.normal.y, 0.5);
        }
        const bool in_glass = v.position.x > 1 - 1e-9 && v.position.x < 1.5 + 1e-9 &&
                              v.position.y > 0.5 - 1e-9 && v.position.y < 1 + 1e-9 &&
                              v.position.z > 1 - 1e-9 && v.position.z < 1.5 + 1e-9;
        if (in_glass) {
            EXPECT_EQ(v.sealed, 0) << "light passes the glass box";
        }
    }
    EXPECT_GT(floor_tops, 4);
    // From inside the floor slab its inside is what shows.
    const auto inside = render::radiosity::build_scene_mesh(frame.geometry(), 0.5, {}, &in_floor);
    for (const auto& v : inside.vertices)
        if (top_of_floor(v)) {
            EXPECT_EQ(v.sealed, 0);
        }
    // Without an eye nothing is sealed.
    for (const auto& v : render::radiosity::build_scene_mesh(frame.geometry(), 0.5).vertices)
        EXPECT_EQ(v.sealed, 0);
    // The reuse key follows the sealing: the camera moving into the slab is a new solution.
    const auto o = small();
    EXPECT_NE(render::radiosity::solution_key(frame, seen, o),
              render::radiosity::solution_key(frame, inside, o));
}

TEST(RadiosityPass, CeilingGetsOnlyIndirectLightAndNoNaN) {
    SourceManager sources;
    RadiosityPass pass;
    std::vector<std::string> log;
    const scene::Scene s = parse(sources, room(-5));
    const render::IndirectLight* light = pass.prepare(s, small(), view(), log);
    ASSERT_NE(light, nullptr);
    double ceiling = 0, floor = 0;
    for (const glm::dvec3& g : pass.solution()->G) {
        ASSERT_TRUE(std::isfinite(g.x + g.y + g.z));
        EXPECT_GE(std::min({g.x, g.y, g.z}), 0.0);
    }
    // Sample the hook on the ceiling's underside and the floor's top through the tracer's API.
    render::Geometry geometry(s);
    render::ThreadState state;
    render::Hit hit;
    ASSERT_TRUE(geometry.intersect(render::Ray{{0.5, 1, 0.3}, {0, 1, 0}}, 1e-4, 1e9, hit));
    ceiling = light->incident(hit, {0, -1, 0}, state).x;
    ASSERT_TRUE(geometry.intersect(render::Ray{{0.5, 1, 0.3}, {0, -1, 0}}, 1e-4, 1e9, hit));
    floor = light->incident(hit, {0, 1, 0}, state).x;
    EXPECT_GT(ceiling, 0.05);  // the lit floor (ρ 0.8) fills most of its hemisphere
    EXPECT_GT(floor, 0.0);     // the ceiling, lit only indirectly, bounces back (bounce 2)
    EXPECT_LT(floor, ceiling);
}

// One bounce (recursion_limit 1) is B = E + ρH: the solve skips the form factors, whose G
// would only stand in for what the display does not gather, and a point the camera did not
// see (here the floor, under a camera looking up at the ceiling) gathers for itself, close to
// what the form factors would have given it; never the zero of an ungathered vertex.
TEST(RadiosityPass, OneBounceSkipsFormFactorsAndGathersWhatItDidNotSee) {
    SourceManager sources;
    std::string text = room(0, 0.8, "radiosity { recursion_limit 1 }");
    text.replace(text.find("look_at <0, 1, 0>"), 17, "look_at <0, 2, 0.01> angle 20");
    const scene::Scene s = parse(sources, text);
    auto options = small();
    options.ff_rays = 0;  // the default
    EXPECT_FALSE(render::radiosity::needs_form_factors(s, options));
    auto named = options;
    named.ff_rays = 16;
    EXPECT_TRUE(render::radiosity::needs_form_factors(s, named));
    auto deeper = options;
    deeper.bounces = 2;
    EXPECT_TRUE(render::radiosity::needs_form_factors(s, deeper));

    render::Geometry geometry(s);
    render::ThreadState state;
    render::Hit floor_hit, ceiling_hit;
    ASSERT_TRUE(geometry.intersect(render::Ray{{0.5, 1, 0.3}, {0, -1, 0}}, 1e-4, 1e9, floor_hit));
    ASSERT_TRUE(geometry.intersect(render::Ray{{0, 1, 0}, {0, 1, 0}}, 1e-4, 1e9, ceiling_hit));
    auto incident = [&](const render::radiosity::RadiosityOptions& o, std::string& line,
                        size_t& g_size, double& ceiling) {
        RadiosityPass pass;
        std::vector<std::string> log;
        const render::IndirectLight* light = pass.prepare(s, o, view(), log);
        EXPECT_NE(light, nullptr);
        if (!light) return 0.0;
        line = pass.summary();
        g_size = pass.solution()->G.size();
        ceiling = light->incident(ceiling_hit, {0, -1, 0}, state).x;
        return light->incident(floor_hit, {0, 1, 0}, state).x;
    };
    std::string skipped_line, named_line;
    size_t skipped_g = 0, named_g = 0;
    double skipped_ceiling = 0, named_ceiling = 0;
    const double skipped = incident(options, skipped_line, skipped_g, skipped_ceiling);
    const double with_ff = incident(named, named_line, named_g, named_ceiling);
    EXPECT_NE(skipped_line.find("no form factors (one bounce)"), std::string::npos) << skipped_line;
    EXPECT_EQ(named_line.find("no form factors"), std::string::npos) << named_line;
    EXPECT_EQ(skipped_g, 0u);
    EXPECT_GT(named_g, 0u);
    // The seen ceiling is gathered either way (its smoothing no longer mixes in the form
    // factors' values of unseen neighbours); the unseen floor sees the ceiling's direct light
    // only through its own gather.
    EXPECT_NEAR(skipped_ceiling, named_ceiling, 0.05 * named_ceiling);
    EXPECT_GT(with_ff, 0.01);
    EXPECT_NEAR(skipped, with_ff, 0.3 * with_ff);
}

// A vertex's direct light is the area mean of its elements' samples at their centroids (on
// the true surface): a speck of shadow on the vertex itself no longer darkens every element
// around it, and a sphere's chords, inside the sphere, still see the light above them.
TEST(RadiosityPass, DirectLightSamplesTheElementsNotTheirCorners) {
    SourceManager sources;
    const scene::Scene s = parse(sources,
                                 "#version 3.7; global_settings { radiosity { recursion_limit 1 } }\n"
                                 "camera { location <0, 5, -5> look_at <0, 0, 0> }\n"
                                 "light_source { <0, 20, 0> rgb 1 }\n"
                                 "box { <-2, -0.1, -2>, <2, 0, 2> pigment { rgb 0.5 } }\n"
                                 "sphere { <0, 0.05, 0>, 0.04 pigment { rgb 0.5 } }\n"
                                 "sphere { <5, 1, 0>, 0.5 pigment { rgb 0.5 } }\n");
    const render::RenderFrame frame(s);
    const auto mesh = render::radiosity::build_scene_mesh(frame.geometry(), 1.0);
    const auto H = render::radiosity::direct_light(frame, mesh, 2);
    double speck = -1, open = -1, top = -1, top_y = -1;
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        const auto& mv = mesh.vertices[v];
        const double h = (mv.normal.y > 0 ? H[2 * v] : H[2 * v + 1]).x;
        if (glm::length(mv.position - glm::dvec3(0, 0, 0)) < 1e-9) speck = h;
        if (glm::length(mv.position - glm::dvec3(1, 0, 1)) < 1e-9) open = h;
        if (glm::length(mv.position - glm::dvec3(5, 1, 0)) < 0.51 && mv.position.y > top_y)
            top_y = mv.position.y, top = H[2 * v].x;
    }
    ASSERT_GT(open, 0.5);  // lit from straight above
    EXPECT_GT(speck, 0.8 * open);  // its own sample lies in the speck's shadow
    ASSERT_GT(top_y, 1.3);
    EXPECT_GT(top, 0.5 * open);
}

// One far object makes the default patches huge: a floor element then fills the view, and
// its corners, far outside the image, see nothing of a small emitter near the camera. The
// preview splits what is seen wider than 1/8 of the image, so the floor beside the emitter
// is lit (advanced/blocks/stackernight.pov's floor was black).
TEST(RadiosityPass, ElementsSeenTooWideSplit) {
    SourceManager sources;
    const scene::Scene s = parse(sources,
        "#version 3.7; global_settings { radiosity { count 100 recursion_limit 1 } }\n"
        "camera { location <0, 3, -6> look_at <0, 0, 0> }\n"
        "plane { y, 0 pigment { rgb 1 } finish { diffuse 1 } }\n"
        "box { -0.5, 0.5 translate <0, 0.5, 0> pigment { rgb 1 } finish { emission 1 diffuse 0 } }\n"
        "box { -0.3, 0.3 translate <-1.5, 0.3, 0> pigment { rgb 1 } }\n"
        "box { -0.5, 0.5 translate <400, 0.5, 600> pigment { rgb 1 } }\n");
    auto floor_beside_emitter = [&](double max_span) {
        RadiosityPass pass;
        std::vector<std::string> log;
        auto o = small();
        o.patch_size = 0;  // the default, from the bounds
        o.subdivision.max_span = max_span;
        const render::IndirectLight* light = pass.prepare(s, o, view(), log);
        EXPECT_NE(light, nullptr);
        if (!light) return 0.0;
        render::Geometry geometry(s);
        render::ThreadState state;
        render::Hit hit;
        EXPECT_TRUE(geometry.intersect(render::Ray{{0.9, 1, -0.2}, {0, -1, 0}}, 1e-4, 1e9, hit));
        return light->incident(hit, {0, 1, 0}, state).x;
    };
    // An emitter filling about a quarter of the hemisphere above: G about 0.25.
    EXPECT_GT(floor_beside_emitter(1.0 / 8), 0.1);
    EXPECT_LT(floor_beside_emitter(0), 0.02) << "the huge element's corners see no light";
}

// A gather starts on the true surface under its vertex. Where a scene places copies of an
// object on top of each other the tracer answers with either copy, and a vertex of the other
// copy still finds its surface (patio-radio_36.pov's balcony rails gathered from inside their
// cylinders, under their chords, and showed black).
TEST(RadiosityPass, GathersFindTheSurfaceOfCoincidentCopies) {
    SourceManager sources;
    // Two coincident objects: a probe from a chord's point below the top (as a coarse
    // facet's vertex would be) for the one the tracer does not answer with.
    auto probe_hidden_one = [&](const std::string& objects, double& landed) {
        const scene::Scene s = parse(sources,
            "#version 3.7; global_settings { radiosity { } }\n"
            "camera { location <0, 3, -6> look_at <0, 0, 0> }\n" + objects);
        const render::RenderFrame frame(s);
        const auto& placed = frame.geometry().placed_objects();
        EXPECT_EQ(placed.size(), 2u);
        if (placed.size() != 2) return false;
        render::Hit hit;
        EXPECT_TRUE(frame.geometry().intersect(render::Ray{{0, 5, 0}, {0, -1, 0}}, 1e-4, 1e9, hit));
        const scene::Object* hidden = hit.object == placed[0].object ? placed[1].object : placed[0].object;
        glm::dvec3 p(0, 0.9, 0), n(0, 1, 0);
        const bool found = render::radiosity::onto_surface(frame.geometry(), hidden, p, n, 0.5);
        landed = p.y;
        return found;
    };
    double y = 0;
    EXPECT_TRUE(probe_hidden_one(
        "#declare C = union { cylinder { <0, 0, -5>, <0, 0, 5>, 1 pigment { rgb 1 } } }\n"
        "object { C } object { C rotate 180 * z }\n", y)) << "copies of one declaration";
    EXPECT_NEAR(y, 1.0, 1e-9);
    EXPECT_FALSE(probe_hidden_one("cylinder { <0, 0, -5>, <0, 0, 5>, 1 pigment { rgb 1 } }\n"
                                  "cylinder { <0, 0, -5>, <0, 0, 5>, 1 pigment { rgb 1 } }\n", y))
        << "two declarations are two objects";
}

// A gather that starts inside solid matter (under a box standing on the floor) is told
// apart: its rays meet the box from behind. With the eye inside the box they are ordinary.
TEST(RadiosityPass, GathersKnowWhenTheyStartInsideSolidMatter) {
    SourceManager sources;
    const scene::Scene s = parse(sources,
        "#version 3.7; global_settings { radiosity { } }\n"
        "camera { location <0, 3, -6> look_at <0, 0, 0> }\n"
        "plane { y, 0 pigment { rgb 1 } }\n"
        "box { <-1, 0, -1>, <1, 1, 1> pigment { rgb 1 } }\n");
    const render::RenderFrame frame(s);
    const glm::dvec3 eye(0, 3, -6), in_box(0, 0.5, 0);
    const auto mesh = render::radiosity::build_scene_mesh(frame.geometry(), 0.5, {}, &eye);
    const std::vector<glm::dvec3> B(mesh.unknowns(), glm::dvec3(0.5));
    auto gather = [&](const render::radiosity::SceneMesh& m, const glm::dvec3& at) {
        return render::radiosity::gather_point(s, m, frame.geometry(), B, at, {0, 1, 0}, 64, 7);
    };
    const auto under = gather(mesh, {0, 1e-4, 0});
    EXPECT_GT(under.inside, 0.99);
    const auto edge = gather(mesh, {1 + 1e-4, 1e-4, 0});  // on the floor beside the box
    EXPECT_LT(edge.inside, 0.01) << "a point outside the box, beside it, is not inside";
    const auto open = gather(mesh, {5, 1e-4, 5});
    EXPECT_EQ(open.inside, 0.0);
    // The camera inside the box: its inside is space one can see.
    const auto seen = render::radiosity::build_scene_mesh(frame.geometry(), 0.5, {}, &in_box);
    EXPECT_EQ(gather(seen, {0, 1e-4, 0}).inside, 0.0);
    // Without an eye nothing is solid.
    const auto plain = render::radiosity::build_scene_mesh(frame.geometry(), 0.5);
    EXPECT_EQ(gather(plain, {0, 1e-4, 0}).inside, 0.0);
}

TEST(RadiosityPass, SolutionFileRoundTripAndMismatch) {
    SourceManager sources;
    RadiosityPass pass;
    std::vector<std::string> log;
    const scene::Scene s = parse(sources, room(-5));
    auto o = small();
    const auto path = (std::filesystem::temp_directory_path() / "lumen_radiosity_test.sol").string();
    o.file = path;
    o.to_file = true;
    ASSERT_NE(pass.prepare(s, o, view(), log), nullptr);
    const auto saved = *pass.solution();
    const auto loaded = render::radiosity::load_solution(path, key_of(s, o), saved.B.size());
    ASSERT_EQ(loaded.B.size(), saved.B.size());
    for (size_t i = 0; i < saved.B.size(); ++i) {
        EXPECT_EQ(loaded.B[i], saved.B[i]);
        EXPECT_EQ(loaded.G[i], saved.G[i]);
        EXPECT_EQ(loaded.indirect[i], saved.indirect[i]);
    }
    EXPECT_THROW(render::radiosity::load_solution(path, key_of(s, o) + 1, saved.B.size()),
                 LumenError);
    EXPECT_THROW(render::radiosity::load_solution(path, key_of(s, o), saved.B.size() + 2),
                 LumenError);
    // Loading through the pass gives the same values.
    RadiosityPass again;
    o.to_file = false;
    o.from_file = true;
    ASSERT_NE(again.prepare(s, o, view(), log), nullptr);
    EXPECT_EQ(again.solution()->G, saved.G);
    std::filesystem::remove(path);
}

// Reflectance >= 1 is reported where the solve runs to convergence (Radiosity_Bounces=0),
// not where POV's recursion_limit stops the bounces anyway.
TEST(RadiosityPass, ReflectanceAtLeastOneIsReported) {
    SourceManager sources;
    const scene::Scene s = parse(sources, room(-5, 1.2));
    auto reported = [&](const render::radiosity::RadiosityOptions& o) {
        RadiosityPass pass;
        std::vector<std::string> log;
        EXPECT_NE(pass.prepare(s, o, view(), log), nullptr);
        bool said = false;
        for (const std::string& l : log) said |= l.find("reflectance >= 1") != std::string::npos;
        for (const glm::dvec3& g : pass.solution()->G) EXPECT_TRUE(std::isfinite(g.x + g.y + g.z));
        return said;
    };
    auto converged = small();
    converged.bounces = 0;
    EXPECT_TRUE(reported(converged));
    EXPECT_FALSE(reported(small()));  // the room's recursion_limit 2
}

// The three form factor methods on a scene mesh agree on the indirect light: ray casting
// with many rays is the reference; analytic (Lambert plus visibility near the vertex) and the
// hemicube must land within a few percent of it, and the +V line names the method.
TEST(RadiosityPass, FormFactorMethodsAgreeOnAScene) {
    SourceManager sources;
    const scene::Scene s = parse(sources, room(-5));
    auto mean_G = [&](render::radiosity::FormFactorMethod m, int rays, int res, std::string& line) {
        RadiosityPass pass;
        std::vector<std::string> log;
        auto o = small();
        o.form_factors = m;
        o.ff_rays = rays;
        o.hemicube_res = res;
        o.bounces = 3;
        o.patch_size = 0.5;
        EXPECT_NE(pass.prepare(s, o, view(), log), nullptr);
        for (const std::string& l : log) EXPECT_EQ(l.find("not available"), std::string::npos);
        line = pass.summary();
        // Over the vertex sides of the floor's top and the ceiling's underside that face
        // into the room (not the boxes' insides, where thin-box corners leak).
        const auto mesh = render::radiosity::build_scene_mesh(
            render::RenderFrame(s).geometry(), o.patch_size);
        double sum = 0;
        int n = 0;
        for (size_t u = 0; u < mesh.unknowns(); ++u) {
            const auto& v = mesh.vertices[u / 2];
            const glm::dvec3 normal = u % 2 ? -v.normal : v.normal;
            const bool face = std::fabs(v.position.y) < 1e-9 || std::fabs(v.position.y - 2) < 1e-9;
            if (!face || std::max(std::fabs(v.position.x), std::fabs(v.position.z)) > 1.99 ||
                normal.y * (1 - v.position.y) <= 0)
                continue;
            sum += pass.solution()->G[u].x;
            ++n;
        }
        EXPECT_GT(n, 20);
        return sum / n;
    };
    using F = render::radiosity::FormFactorMethod;
    std::string line;
    const double reference = mean_G(F::RayCast, 1024, 0, line);
    EXPECT_GT(reference, 0.01);
    const double analytic = mean_G(F::Analytic, 64, 0, line);
    EXPECT_NE(line.find("(analytic 64 rays)"), std::string::npos) << line;
    EXPECT_NEAR(analytic / reference, 1.0, 0.03);
    const double cube = mean_G(F::Hemicube, 0, 24, line);
    EXPECT_NE(line.find("(hemicube resolution 24)"), std::string::npos) << line;
    EXPECT_NEAR(cube / reference, 1.0, 0.03);
}

// The gather display (per-pixel gathers through the irradiance cache) and the preview show
// the same indirect light on the ceiling, lit only indirectly, within their ray noise.
TEST(RadiosityPass, GatherDisplayAgreesWithThePreview) {
    SourceManager sources;
    const scene::Scene s = parse(sources, room(-5));
    render::Geometry geometry(s);
    render::ThreadState state;
    auto ceiling_mean = [&](render::radiosity::DisplayMode mode, size_t& cache_points) {
        RadiosityPass pass;
        std::vector<std::string> log;
        auto o = small();
        o.display = mode;
        o.gather_rays = 1024;
        o.cache_error = 0.1;
        o.patch_size = 0.25;  // fine: the preview's linear interpolation flattens the peak
        const render::IndirectLight* light = pass.prepare(s, o, view(), log);
        EXPECT_NE(light, nullptr);
        double sum = 0;
        int n = 0;
        for (double x = -0.24; x <= 0.25; x += 0.04)
            for (double z = -0.24; z <= 0.25; z += 0.04) {
                render::Hit hit;
                EXPECT_TRUE(geometry.intersect(render::Ray{{x, 1, z}, {0, 1, 0}}, 1e-4, 1e9, hit));
                const glm::dvec3 g = light->incident(hit, {0, -1, 0}, state);
                EXPECT_TRUE(std::isfinite(g.x + g.y + g.z));
                sum += g.x;
                ++n;
            }
        const auto* stats = dynamic_cast<const render::radiosity::GatherStats*>(light);
        cache_points = stats ? stats->cache_points() : 0;
        return sum / n;
    };
    size_t preview_points = 0, gather_points = 0;
    const double preview = ceiling_mean(render::radiosity::DisplayMode::Preview, preview_points);
    const double gather = ceiling_mean(render::radiosity::DisplayMode::Gather, gather_points);
    EXPECT_GT(preview, 0.05);
    EXPECT_NEAR(gather / preview, 1.0, 0.05);
    EXPECT_EQ(preview_points, 0u);
    // 169 lookups reuse records: far fewer gathers than points.
    EXPECT_GT(gather_points, 0u);
    EXPECT_LT(gather_points, 60u);
}

// Direct light enters the solution as POV's diffuse term, cos^brilliance: a floor vertex
// whose light arrives at 60 degrees (cos 0.5) gets half the first-bounce radiosity with
// brilliance 2 that it gets with brilliance 1.
TEST(RadiosityPass, BrillianceShapesTheDirectLight) {
    auto first_bounce = [](double brilliance) {
        SourceManager sources;
        const std::string text =
            "#version 3.7; global_settings { radiosity { recursion_limit 1 } }\n"
            "camera { location <0, 5, -5> look_at <0, 0, 0> }\n"
            // Far off (60 degrees from the normal everywhere on the floor): the direct light
            // is sampled over the elements around the vertex, not at the vertex alone.
            "light_source { <0, 1000, -1732.0508075688772> rgb 1 }\n"
            "box { <-2, -0.1, -2>, <2, 0, 2> pigment { rgb 0.5 } finish { diffuse 1 brilliance " +
            std::to_string(brilliance) + " } }\n";
        const scene::Scene s = parse(sources, text);
        RadiosityPass pass;
        std::vector<std::string> log;
        EXPECT_NE(pass.prepare(s, small(), view(), log), nullptr);
        const auto mesh = render::radiosity::build_scene_mesh(
            render::RenderFrame(s).geometry(), small().patch_size);
        for (size_t v = 0; v < mesh.vertices.size(); ++v)
            if (glm::length(mesh.vertices[v].position) < 1e-9 && mesh.vertices[v].normal.y > 0.5)
                return pass.solution()->B[2 * v].x;
        ADD_FAILURE() << "no vertex at the origin";
        return 0.0;
    };
    const double one = first_bounce(1), two = first_bounce(2);
    EXPECT_GT(one, 0.05);
    EXPECT_NEAR(two / one, 0.5, 1e-3);  // cos 60 degrees, squared against once
}

// Gauss-Seidel and progressive refinement run on the sparse rows: a mesh of more than the
// dense solvers' 6000 unknowns converges, to the same light as Jacobi run to convergence.
TEST(RadiosityPass, SparseSolversHaveNoUnknownCap) {
    SourceManager sources;
    const scene::Scene s = parse(sources, room(-5));
    auto solve = [&](render::radiosity::Method m) {
        RadiosityPass pass;
        std::vector<std::string> log;
        auto o = small();
        o.patch_size = 0.1;
        o.ff_rays = 4;
        o.gather_rays = 4;
        o.bounces = 0;  // converge
        o.method = m;
        o.tolerance = 1e-7;
        EXPECT_NE(pass.prepare(s, o, view(), log), nullptr);
        for (const std::string& l : log) ADD_FAILURE() << l;
        EXPECT_GT(pass.solution()->B.size(), 6000u);
        return pass.solution()->B;
    };
    using M = render::radiosity::Method;
    const auto jacobi = solve(M::Jacobi), gs = solve(M::GaussSeidel), pr = solve(M::Progressive);
    double worst = 0, size = 0;
    for (size_t u = 0; u < jacobi.size(); ++u)
        for (int k = 0; k < 3; ++k) {
            worst = std::max({worst, std::abs(gs[u][k] - jacobi[u][k]),
                              std::abs(pr[u][k] - jacobi[u][k])});
            size = std::max(size, jacobi[u][k]);
        }
    EXPECT_GT(size, 0.1);
    EXPECT_LT(worst, 1e-4 * size);
}

// Gather rays that leave the scene see the sky_sphere (over the background), as POV's
// radiosity rays do: an open floor's upward side gathers exactly the sky's colour.
TEST(RadiosityPass, EscapingRaysSeeTheSkySphere) {
    SourceManager sources;
    const scene::Scene s = parse(sources,
                                 "#version 3.7; global_settings { radiosity { recursion_limit 1 } }\n"
                                 "background { rgb 0.9 }\n"
                                 "sky_sphere { pigment { rgb <0.25, 0.5, 0.75> } }\n"
                                 "camera { location <0, 5, -5> look_at <0, 0, 0> }\n"
                                 "box { <-2, -0.1, -2>, <2, 0, 2> pigment { rgb 0.5 } }\n");
    RadiosityPass pass;
    std::vector<std::string> log;
    ASSERT_NE(pass.prepare(s, small(), view(), log), nullptr);
    for (const std::string& l : log) EXPECT_EQ(l.find("sky_sphere"), std::string::npos) << l;
    const auto mesh = render::radiosity::build_scene_mesh(
            render::RenderFrame(s).geometry(), small().patch_size);
    int checked = 0;
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        if (std::fabs(mesh.vertices[v].position.y) > 1e-9 || mesh.vertices[v].normal.y < 0.5) continue;
        const glm::dvec3 g = pass.solution()->G[2 * v];
        EXPECT_NEAR(g.x, 0.25, 1e-9);
        EXPECT_NEAR(g.y, 0.5, 1e-9);
        EXPECT_NEAR(g.z, 0.75, 1e-9);
        ++checked;
    }
    EXPECT_GT(checked, 10);
}

}  // namespace
}  // namespace lumen::cli
