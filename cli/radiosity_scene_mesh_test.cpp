// The radiosity mesh's materials on scenes read from SDL: each patch reflects with the texture
// the renderer shows there.
#include <gtest/gtest.h>

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
