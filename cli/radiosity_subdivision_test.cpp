// Adaptive subdivision of the receiving elements through the radiosity pass: elements split
// where the gathered indirect light changes (a block's contact with the floor), not where it
// is uniform, and never beyond the vertex budget.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cli/radiosity_pass.hpp"
#include "interp/interpret.hpp"

namespace lumen::cli {
namespace {

namespace rad = render::radiosity;

// An 8x8 floor seen from above; `extra` adds objects.
std::string floor_scene(const std::string& extra, const char* background = "rgb 0") {
    return std::string("#version 3.7; global_settings { radiosity { recursion_limit 1 } }\n") +
           "background { " + background + " }\n"
           "camera { location <0, 9, -0.01> look_at <0, 0, 0> angle 60 }\n"
           "light_source { <3, 8, -2> rgb 1 }\n"
           "box { <-4, -0.1, -4>, <4, 0, 4> pigment { rgb 0.8 } finish { diffuse 0.8 } }\n" +
           extra;
}

rad::RadiosityOptions options() {
    rad::RadiosityOptions o;
    o.patch_size = 0.5;
    o.ff_rays = 16;
    o.gather_rays = 256;
    o.display = rad::DisplayMode::Preview;
    return o;
}

render::RenderOptions view() {
    render::RenderOptions r;
    r.width = 80;
    r.height = 80;
    r.threads = 2;
    return r;
}

struct Prepared {
    SourceManager sources;
    scene::Scene scene;
    RadiosityPass pass;
    std::vector<std::string> log;
};

void prepare(Prepared& p, const std::string& text, const rad::RadiosityOptions& o) {
    p.scene = interp::interpret_text(p.sources, "floor.pov", text, {});
    ASSERT_NE(p.pass.prepare(p.scene, o, view(), p.log), nullptr);
    ASSERT_NE(p.pass.receivers(), nullptr);
}

// Split triangles (depth > 0) on the floor's top face, by distance from the block's
// footprint |x|, |z| <= 1: within 0.75 of it, and beyond 2 of it (a ring of the same width
// further out, |x|, |z| in (3, 3.75]).
void count_splits(const rad::ReceiverMesh& r, int& near, int& far) {
    near = far = 0;
    for (const auto& t : r.leaves) {
        if (t.depth == 0) continue;
        glm::dvec3 c(0);
        for (uint32_t v : t.v) c += r.position(v) / 3.0;
        if (std::fabs(c.y) > 1e-9) continue;  // not the floor's top
        const double d = std::max(std::fabs(c.x), std::fabs(c.z));
        if (d > 1 && d <= 1.75) ++near;
        if (d > 3 && d <= 3.75) ++far;
    }
}

TEST(RadiositySubdivision, SplitsAtTheContactNotInTheOpen) {
    Prepared p;
    // A budget that runs out before every element is down to the smallest: the worst (the
    // contact) must come first. (With the default 2 the open floor's ray noise splits too.)
    rad::RadiosityOptions o = options();
    o.subdivision.budget = 0.5;
    prepare(p, floor_scene("box { <-1, 0, -1>, <1, 1.5, 1> pigment { rgb 0.8 } finish { diffuse 0.8 } }\n"),
            o);
    const rad::ReceiverMesh& r = *p.pass.receivers();
    int near = 0, far = 0;
    count_splits(r, near, far);
    // The far ring is 1.9x the near ring's area: the contact must still win clearly.
    EXPECT_GT(r.split, 0u);
    EXPECT_GT(near, 2 * far + 8) << "near " << near << ", far " << far;
    EXPECT_NE(p.pass.summary().find("elements split"), std::string::npos);
}

TEST(RadiositySubdivision, StaysWithinTheBudget) {
    Prepared p;
    auto o = options();
    o.subdivision.budget = 0.05;
    o.subdivision.tolerance = 0.01;  // everything disagrees: only the budget stops it
    prepare(p, floor_scene("box { <-1, 0, -1>, <1, 1.5, 1> pigment { rgb 0.8 } finish { diffuse 0.8 } }\n"),
            o);
    const rad::ReceiverMesh& r = *p.pass.receivers();
    EXPECT_GT(r.split, 0u);
    // Vertex sides gathered before splitting: those the camera saw (the summary's count).
    const std::string line = p.pass.summary();
    const size_t at = line.find(" vertices");
    const size_t start = line.rfind('(', at) + 1;
    const double gathered = std::stod(line.substr(start, at - start));
    EXPECT_LE(double(r.added_vertices()), 0.05 * gathered);
    EXPECT_GT(double(r.added_vertices()), 0.05 * gathered - 3);  // it used the budget
}

TEST(RadiositySubdivision, NoElementSplitsBelowThePixelLimit) {
    const std::string block =
        "box { <-1, 0, -1>, <1, 1.5, 1> pigment { rgb 0.8 } finish { diffuse 0.8 } }\n";
    // The camera 9 above the floor, 60 degrees over 80 pixels: a pixel spans at least
    // 9 x 2 tan 30 / 80 = 0.13 on the floor, the elements 0.5 to 0.7.
    const double pixel = 9 * 2 * std::tan(M_PI / 6) / 80;
    {
        Prepared p;
        auto o = options();
        o.subdivision.min_pixels = 8;  // 1.04: no element is that long
        prepare(p, floor_scene(block), o);
        EXPECT_EQ(p.pass.receivers()->split, 0u);
    }
    Prepared p;
    prepare(p, floor_scene(block), options());  // the default, 3 pixels
    const rad::ReceiverMesh& r = *p.pass.receivers();
    EXPECT_GT(r.split, 0u);
    for (const auto& t : r.leaves) {
        if (t.depth == 0) continue;
        double longest = 0;
        for (int k = 0; k < 3; ++k)
            longest = std::max(longest, glm::length(r.position(t.v[k]) - r.position(t.v[(k + 1) % 3])));
        EXPECT_GE(longest, 1.5 * pixel);  // a child of an element at least 3 pixels long
    }
}

TEST(RadiositySubdivision, UniformLightSplitsNothing) {
    Prepared p;
    // Nothing above the floor: every gather ray escapes to the same background.
    prepare(p, floor_scene("", "rgb 0.5"), options());
    EXPECT_EQ(p.pass.receivers()->split, 0u);
    EXPECT_EQ(p.pass.receivers()->added_vertices(), 0u);
}

TEST(RadiositySubdivision, OffLeavesTheMeshAsItIs) {
    Prepared p;
    auto o = options();
    o.subdivision.enabled = false;
    prepare(p, floor_scene("box { <-1, 0, -1>, <1, 1.5, 1> pigment { rgb 0.8 } finish { diffuse 0.8 } }\n"),
            o);
    EXPECT_EQ(p.pass.receivers()->split, 0u);
    EXPECT_EQ(p.pass.summary().find("elements split"), std::string::npos);
}

}  // namespace
}  // namespace lumen::cli
