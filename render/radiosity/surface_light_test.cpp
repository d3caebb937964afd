// What radiosity reads of a surface's layered texture: the layers below show through the
// filter and transmit of those above, as the tracer shows them.
#include <memory>

#include <gtest/gtest.h>

#include "render/radiosity/surface_light.hpp"

namespace lumen::render::radiosity {
namespace {

scene::TexturePtr layer(scene::Colour c, double ambient, double diffuse) {
    auto pigment = std::make_shared<scene::Pigment>();
    pigment->colour = c;
    auto finish = std::make_shared<scene::Finish>();
    finish->ambient = glm::dvec3(ambient);
    finish->diffuse = diffuse;
    auto texture = std::make_shared<scene::Texture>();
    texture->pigment = pigment;
    texture->finish = finish;
    return texture;
}

void expect_near(const glm::dvec3& a, const glm::dvec3& b) {
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], 1e-12) << "channel " << i;
}

// advanced/balcony's sky: clouds (transmit 1 where the sky is clear) over a blue layer of
// ambient 1, which must emit where the clouds let it through.
TEST(SurfaceMaterial, LowerLayersShowThroughTransmit) {
    const scene::LayeredTexture sky = {layer({0.4, 0.55, 0.9, 0, 0}, 1, 0),
                                       layer({1, 1, 1, 0, 1}, 1, 0)};
    const SurfaceMaterial m = surface_material(&sky, glm::dvec3(0), glm::dvec3(1));
    expect_near(m.emission, {0.4, 0.55, 0.9});
    expect_near(m.rho, glm::dvec3(0));
    EXPECT_TRUE(never_diffuse(&sky));
}

// A half-filtering red top layer over a white diffuse one: ρ = top's share + what its filter
// (rgb · filter + transmit) passes of the lower layer.
TEST(SurfaceMaterial, FilterTintsTheLayerBelow) {
    const scene::LayeredTexture t = {layer({1, 1, 1, 0, 0}, 0, 0.5),
                                     layer({1, 0, 0, 0.5, 0.25}, 0, 0.8)};
    const SurfaceMaterial m = surface_material(&t, glm::dvec3(0), glm::dvec3(1));
    // Top: opacity 1 - 0.5 - 0.25 = 0.25; it passes rgb·0.5 + 0.25 = (0.75, 0.25, 0.25).
    expect_near(m.rho, {0.8 * 0.25 + 0.75 * 0.5, 0.25 * 0.5, 0.25 * 0.5});
    EXPECT_FALSE(never_diffuse(&t));
}

}  // namespace
}  // namespace lumen::render::radiosity
