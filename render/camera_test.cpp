#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "render/camera.hpp"

namespace lumen::render {
namespace {

TEST(Camera, DefaultPerspectiveUsesHalfPixelOffsetAndFlipsY) {
    scene::Camera c;  // right 1.33, up 1, direction 1
    const CameraModel cam(c, 64, 48);
    const Ray top_left = cam.ray(0, 0);
    const glm::dvec3 expected =
        glm::normalize(glm::dvec3((0.5 / 64 - 0.5) * 1.33, 0.5 - 0.5 / 48, 1.0));
    EXPECT_NEAR(top_left.dir.x, expected.x, 1e-12);
    EXPECT_NEAR(top_left.dir.y, expected.y, 1e-12);
    EXPECT_GT(top_left.dir.y, 0);  // the top row looks up
    EXPECT_NEAR(glm::length(cam.ray(17.3, 5.2).dir), 1.0, 1e-12);
    // The centre of the image lies between pixels 31 and 32.
    const Ray centre = cam.ray(31.5, 23.5);
    EXPECT_NEAR(centre.dir.x, 0, 1e-12);
    EXPECT_NEAR(centre.dir.y, 0, 1e-12);
}

TEST(Camera, OrthographicMovesTheOriginNotTheDirection) {
    scene::Camera c;
    c.type = scene::CameraType::Orthographic;
    c.location = {0, 0, -10};
    c.right = {4, 0, 0};
    c.up = {0, 3, 0};
    const CameraModel cam(c, 40, 30);
    const Ray r = cam.ray(0, 0);
    EXPECT_NEAR(r.origin.x, (0.5 / 40 - 0.5) * 4, 1e-12);
    EXPECT_NEAR(r.origin.y, (0.5 - 0.5 / 30) * 3, 1e-12);
    EXPECT_NEAR(r.dir.z, 1, 1e-12);
    EXPECT_NEAR(r.dir.x, 0, 1e-12);
}

TEST(Camera, NegativeRightMirrorsTheImage) {
    scene::Camera c;
    c.right = {-1.33, 0, 0};
    const CameraModel cam(c, 10, 10);
    EXPECT_GT(cam.ray(0, 5).dir.x, 0);
}

}  // namespace
}  // namespace lumen::render
