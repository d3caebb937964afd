// The radiosity mesh's element search (SceneMesh::find_near) in a grid cell crowded by a dense
// mesh, against the plain cell scan it replaces.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "base/diagnostics.hpp"
#include "interp/interpret.hpp"
#include "render/frame.hpp"
#include "render/radiosity/scene_mesh.hpp"

namespace lumen::cli {
namespace {

const std::string kLitFloor =
    "#version 3.7; global_settings { radiosity { recursion_limit 2 } }\n"
    "camera { location <0, 1, -5> look_at <0, 1, 0> }\n"
    "light_source { <0, 1.5, 0> rgb 1 }\n"
    "box { <-2, -0.1, -2>, <2, 0, 2> pigment { rgb 0.8 } finish { diffuse 1 } }\n";

// A bumpy mesh of 3200 small triangles under patches of size 1 crowds a grid cell with
// hundreds of elements, which find_near searches through the object's tree: the answer must
// be the cell scan's (the element nearest by plane distance whose projection holds the
// point, the last such in element order, the first at distance 0), written out here.
TEST(RadiosityElementSearch, FindNearInACrowdedCellAnswersAsTheCellScan) {
    SourceManager sources;
    const std::string bumps =
        "#declare H = function(x, z) { 0.05 * sin(9 * x) * cos(7 * z) }\n"
        "mesh { #for (i, 0, 39) #for (j, 0, 39)\n"
        "  #local X = -1 + i / 20; #local Z = -1 + j / 20; #local D = 1 / 20;\n"
        "  triangle { <X, 1 + H(X, Z), Z>, <X + D, 1 + H(X + D, Z), Z>, <X, 1 + H(X, Z + D), Z + D> }\n"
        "  triangle { <X + D, 1 + H(X + D, Z), Z>, <X + D, 1 + H(X + D, Z + D), Z + D>,"
        " <X, 1 + H(X, Z + D), Z + D> }\n"
        "#end #end pigment { rgb 0.7 } finish { diffuse 1 } }\n";
    const scene::Scene s = interp::interpret_text(sources, "bumps.pov", kLitFloor + bumps, {});
    const render::RenderFrame frame(s);
    const auto mesh = render::radiosity::build_scene_mesh(frame.geometry(), 1.0);
    uint32_t slot = 0;
    size_t most = 0;
    for (uint32_t o = 0; o < mesh.per_object.size(); ++o)
        if (mesh.per_object[o].elements.size() > most) most = mesh.per_object[o].elements.size(), slot = o;
    ASSERT_GE(most, 3200u);
    const double slack = 0.5 * mesh.patch_size;
    auto cell_scan = [&](const glm::dvec3& p, glm::dvec3& bary) {
        const glm::ivec3 c = glm::clamp(glm::ivec3(glm::floor((p - mesh.grid_origin) / mesh.grid_cell)),
                                        glm::ivec3(0), mesh.grid_size - 1);
        const size_t cell = (size_t(c.z) * mesh.grid_size.y + c.y) * mesh.grid_size.x + c.x;
        long best = -1;
        double best_h = slack;
        for (uint32_t k = mesh.cell_start[cell]; k < mesh.cell_start[cell + 1]; ++k) {
            if (mesh.cell_slots[k] != slot) continue;
            const auto& f = mesh.frames[mesh.cell_items[k]];
            const glm::dvec3 ap = p - f.a;
            const double along = glm::dot(ap, f.normal), h = std::fabs(along);
            if (h > best_h || f.inv_det == 0) continue;
            const glm::dvec3 r = ap - along * f.normal;
            const double r1 = glm::dot(r, f.e1), r2 = glm::dot(r, f.e2);
            const double u = (f.d22 * r1 - f.d12 * r2) * f.inv_det,
                         w = (f.d11 * r2 - f.d12 * r1) * f.inv_det;
            if (u < -1e-6 || w < -1e-6 || u + w > 1 + 1e-6) continue;
            const double uc = std::clamp(u, 0.0, 1.0), wc = std::clamp(w, 0.0, 1.0 - uc);
            bary = {1 - uc - wc, uc, wc};
            best = long(mesh.cell_items[k]), best_h = h;
            if (h == 0) break;
        }
        return best;
    };
    size_t crowded = 0;
    for (size_t c = 0; c + 1 < mesh.cell_start.size(); ++c)
        crowded = std::max<size_t>(crowded, mesh.cell_start[c + 1] - mesh.cell_start[c]);
    EXPECT_GT(crowded, 200u);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.1, 1.1), off(-0.3, 0.3);
    int found = 0;
    for (int i = 0; i < 4000; ++i) {
        const double x = u(rng), z = u(rng);
        // On the surface, at a vertex, or off it by up to 0.3.
        glm::dvec3 p(x, 1 + 0.05 * std::sin(9 * x) * std::cos(7 * z), z);
        if (i % 4 == 1) p = mesh.frames[mesh.per_object[slot].elements[i % most]].a;
        if (i % 4 >= 2) p.y += off(rng);
        glm::dvec3 got(-1), want(-1);
        const long e = mesh.find_near(p, slot, slack, got);
        ASSERT_EQ(e, cell_scan(p, want)) << p.x << " " << p.y << " " << p.z;
        if (e < 0) continue;
        ASSERT_EQ(got, want);
        ++found;
    }
    EXPECT_GT(found, 2000);
}

}  // namespace
}  // namespace lumen::cli
