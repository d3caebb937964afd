// The radiosity mesh's stability reports on scenes read from SDL: coincident surfaces facing
// the same way and sliver elements are reported with their source locations; a box resting
// on a floor (surfaces in contact, facing each other), surfaces sharing an edge and overlaps of
// one material are not. The mesh's materials: each patch reflects with the texture the renderer
// shows there.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "interp/interpret.hpp"
#include "render/frame.hpp"
#include "render/radiosity/scene_mesh.hpp"

namespace lumen::cli {
namespace {

render::radiosity::SceneMesh scene_mesh(const std::string& objects) {
    SourceManager sources;
    const scene::Scene scene = interp::interpret_text(
        sources, "mesh.pov",
        "#version 3.7; global_settings { radiosity { } }\n"
        "camera { location <0, 3, -6> look_at 0 }\nlight_source { <2, 5, -3> rgb 1 }\n" +
            objects,
        {});
    return render::radiosity::build_scene_mesh(render::RenderFrame(scene).geometry(), 0.5);
}

std::vector<std::string> mesh_warnings(const std::string& objects) {
    return scene_mesh(objects).warnings;
}

int count_containing(const std::vector<std::string>& w, const std::string& text) {
    return int(std::count_if(w.begin(), w.end(), [&](const std::string& s) {
        return s.find(text) != std::string::npos;
    }));
}

TEST(RadiosityMeshChecks, CoincidentSurfacesAreReportedWithBothLocations) {
    const auto w = mesh_warnings(
        "box { <-1, 0, -1>, <1, 1, 1> pigment { rgb 0.5 } }\n"
        "box { <-1, 0, -1>, <1, 1, 1> pigment { rgb 0.7 } }\n");
    ASSERT_EQ(count_containing(w, "coincides"), 1);
    EXPECT_EQ(count_containing(w, "mesh.pov:4:1: warning: radiosity: this surface coincides "
                                  "with the one at mesh.pov:5:1"),
              1);
}

TEST(RadiosityMeshChecks, ABoxRestingOnAFloorIsNotReported) {
    const auto w = mesh_warnings(
        "box { <-3, -0.5, -3>, <3, 0, 3> pigment { rgb 0.5 } }\n"
        "box { <-1, 0, -1>, <1, 1, 1> pigment { rgb 0.7 } }\n");
    EXPECT_EQ(count_containing(w, "coincides"), 0);
    EXPECT_EQ(count_containing(w, "sliver"), 0);
}

// rad_def_test_37.pov's rim: boxes of one union overlap at the corners, their faces coplanar
// and of one material; and boxes side by side share only an edge of their top faces.
TEST(RadiosityMeshChecks, OverlapsOfOneMaterialAndSharedEdgesAreNotReported) {
    const auto w = mesh_warnings(
        "union { box { <0, 0, 0>, <0.2, 0.16, 0.2> } box { <0, 0, 0>, <0.16, 0.2, 0.2> }\n"
        "        pigment { rgb 0.5 } }\n"
        "box { <1, 0, 0>, <2, 1, 1> pigment { rgb 0.3 } }\n"
        "box { <2, 0, 0>, <3, 1, 1> pigment { rgb 0.6 } }\n"
        "box { <-3.2, -0.2, -3>, <3.2, 0, 3.2> pigment { rgb 0.8 } }\n"
        "box { <-3.2, 0, -3>, <-3, 2, 3.2> pigment { rgb <0.8, 0.2, 0.2> } }\n");
    EXPECT_EQ(count_containing(w, "coincides"), 0);
}

TEST(RadiosityMeshChecks, OverlapsOfDifferentMaterialsAreReported) {
    const auto w = mesh_warnings(
        "box { <0, 0, 0>, <0.2, 0.16, 0.2> pigment { rgb 0.5 } }\n"
        "box { <0, 0, 0>, <0.16, 0.2, 0.2> pigment { rgb 0.6 } }\n");
    EXPECT_GE(count_containing(w, "coincides"), 1);
}

// radiosity/patio-radio_37.pov: columns stand in paving slabs on the ground plane. Their
// bottoms coincide, but they face into the plane's opaque matter, where no ray goes; and the
// slabs' long thin sides are cut finely enough that lumen makes no slivers of its own.
TEST(RadiosityMeshChecks, HiddenCoincidencesAndLongThinFacesAreNotReported) {
    // A slab 8 long and 0.0005 high, and a column standing in it, both with their bottoms at y.
    const std::string slab_and_column =
        "union { box { <-4, 0, -0.5>, <4, 0.0005, 0.5> pigment { rgb 0.7 } }\n"
        "        box { <-0.3, 0, -0.3>, <0.3, 1, 0.3> pigment { rgb 0.9 } } translate y * Y }\n";
    const auto w = mesh_warnings("#declare Y = 0; plane { y, 0 pigment { rgb 0.5 } }\n" +
                                 slab_and_column);
    EXPECT_EQ(count_containing(w, "coincides"), 0);
    EXPECT_EQ(count_containing(w, "sliver"), 0);
    // Lifted off the plane, their bottoms are seen, and do coincide.
    EXPECT_EQ(count_containing(mesh_warnings("#declare Y = 1;\n" + slab_and_column), "coincides"), 1);
}

// clipped_by only takes surface away: the object is meshed whole, with nothing to report
// (patio-radio_37.pov's arches are clipped at the ground).
TEST(RadiosityMeshChecks, ClippedObjectsNeedNoWarning) {
    const auto w = mesh_warnings(
        "sphere { <0, 0.5, 0>, 1 clipped_by { plane { -y, 0 } } pigment { rgb 0.5 } }\n");
    EXPECT_TRUE(w.empty()) << (w.empty() ? "" : w[0]);
}

TEST(RadiosityMeshChecks, SliverTrianglesAreReported) {
    const auto w = mesh_warnings(
        "triangle { <-1, 0, 0>, <1, 0, 0>, <0, 0.0001, 0> pigment { rgb 0.5 } }\n"
        "triangle { <-1, 1, 0>, <1, 1, 0>, <0, 2, 0> pigment { rgb 0.5 } }\n");
    ASSERT_EQ(count_containing(w, "sliver"), 1);
    EXPECT_EQ(count_containing(w, "mesh.pov:4:1: warning: radiosity: "), 1);
}

// A mesh2 with a texture_list and no texture of its own (camera/mesh_camera's room and vases):
// its faces reflect with their own entries, not with the black default texture.
TEST(RadiositySceneMesh, MeshFacesReflectWithTheirTextureListEntries) {
    const auto mesh = scene_mesh(
        "mesh2 { vertex_vectors { 4, <-1, 0, -1>, <1, 0, -1>, <1, 0, 1>, <-1, 0, 1> }\n"
        "  texture_list { 2, texture { pigment { rgb <1, 0, 0> } }\n"
        "                    texture { pigment { rgb <0, 1, 0> } } }\n"
        "  face_indices { 2, <0, 1, 2>, 0, <0, 2, 3>, 1 } }\n");
    int red = 0, green = 0, other = 0;
    for (const auto& v : mesh.vertices) {
        if (v.rho.x > 0 && v.rho.y == 0 && v.rho.z == 0) ++red;
        else if (v.rho.y > 0 && v.rho.x == 0 && v.rho.z == 0) ++green;
        else ++other;
    }
    EXPECT_GT(red, 0);
    EXPECT_GT(green, 0);
    EXPECT_EQ(other, 0);
}

}  // namespace
}  // namespace lumen::cli
