// RenderFrame: the one compiled scene that the pre-passes and the tracer share.
#include <gtest/gtest.h>

#include "base/diagnostics.hpp"
#include "render/frame.hpp"
#include "render/geometry_test_util.hpp"

namespace lumen::render {
namespace {

using namespace testing;

TEST(RenderFrame, HoldsTheLightsLooksLikeObjectsInItsGeometry) {
    scene::Scene s;
    s.objects.push_back(make(scene::Sphere{{0, 0, 0}, 1}));
    scene::Light light;
    light.position = {5, 0, 0};
    auto bulb = make(scene::Sphere{{5, 0, 0}, 0.5});
    bulb->no_shadow = true;
    light.looks_like = bulb;
    s.lights.push_back(light);
    const RenderFrame frame(s);
    EXPECT_EQ(frame.geometry().primitive_count(), 2u);
    auto hit = trace(frame.geometry(), ray({5, 0, -5}, {0, 0, 1}));
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->object, bulb.get());
    ASSERT_EQ(frame.lights().size(), 1u);
    EXPECT_EQ(frame.lights()[0].light, &s.lights[0]);
    // The scene's own objects alone, as Geometry(scene) compiles them.
    EXPECT_EQ(Geometry(s).primitive_count(), 1u);
}

TEST(RenderFrame, RefusesAnUnsupportedFeatureWithItsLocation) {
    scene::Scene s;
    s.unsupported.push_back({"isosurface", {}});
    EXPECT_THROW(RenderFrame{s}, LumenError);
    EXPECT_THROW(check_supported(s), LumenError);
    s.unsupported.clear();
    EXPECT_NO_THROW(check_supported(s));
}

}  // namespace
}  // namespace lumen::render
