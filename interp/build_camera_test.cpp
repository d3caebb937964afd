// Camera fix-ups and light sources, as POV-Ray 3.7 applies them.
#include <cmath>

#include <glm/geometric.hpp>

#include "interp/build_test_support.hpp"

namespace lumen::interp::testing {
namespace {

using BuildCamera = BuildTest;

TEST_F(BuildCamera, DefaultsWhenNoCamera) {
    scene::Camera c = run("sphere { 0, 1 }").camera;
    expect_vec(c.right, {1.33, 0, 0});
    expect_vec(c.direction, {0, 0, 1});
}

TEST_F(BuildCamera, AngleSetsDirectionLengthFromRight) {
    scene::Camera c = run("camera { right x*2 angle 90 }").camera;
    EXPECT_NEAR(glm::length(c.direction), 1.0, 1e-12);  // |R| / (2 tan 45)
}

TEST_F(BuildCamera, LookAtKeepsLengthsAndHandedness) {
    scene::Camera c = run("camera { location <0,0,-5> direction z*2 look_at <5,0,0> }").camera;
    expect_vec(c.location, {0, 0, -5});
    EXPECT_NEAR(glm::length(c.direction), 2, 1e-12);
    expect_vec(glm::normalize(c.direction), glm::normalize(glm::dvec3(5, 0, 5)));
    EXPECT_NEAR(glm::length(c.right), 1.33, 1e-12);
    expect_vec(c.up, {0, 1, 0});
    // right = sky x direction: pointing to +x,-z for a camera looking along +x,+z
    EXPECT_GT(c.right.x, 0);
    EXPECT_LT(c.right.z, 0);
    scene::Camera m = run("camera { right -x*1.33 look_at z }").camera;
    EXPECT_NEAR(m.right.x, -1.33, 1e-12);  // left-handed right stays mirrored
}

TEST_F(BuildCamera, SkyTiltsUp) {
    scene::Camera c = run("camera { sky <1,1,0> look_at z }").camera;
    expect_vec(glm::normalize(c.up), glm::normalize(glm::dvec3(1, 1, 0)));
}

TEST_F(BuildCamera, OrthographicScaledByLookAtDistance) {
    scene::Camera c = run("camera { orthographic location <0,0,-10> look_at 0 }").camera;
    EXPECT_EQ(c.type, scene::CameraType::Orthographic);
    EXPECT_NEAR(glm::length(c.right), 13.3, 1e-9);
    EXPECT_NEAR(glm::length(c.up), 10, 1e-9);
    scene::Camera u = run("camera { orthographic up y*2 right x*2 location <0,0,-10> look_at 0 }").camera;
    EXPECT_NEAR(glm::length(u.up), 2, 1e-9);  // explicit up/right without angle: no scaling
}

TEST_F(BuildCamera, DeclaredOrthographicCameraIsNotSizedAgain) {
    const scene::Camera a = run("camera { orthographic location <0,0,-10> look_at 0 }").camera;
    const scene::Camera b =
        run("#declare C = camera { orthographic location <0,0,-10> look_at 0 } camera { C }").camera;
    expect_vec(b.right, a.right);
    expect_vec(b.up, a.up);
}

TEST_F(BuildCamera, TransformsAppliedLast) {
    scene::Camera c = run("camera { translate x location <0,0,-5> rotate y*90 }").camera;
    expect_vec(c.location, {-5, 0, -1});  // (1,0,-5) rotated about y by 90
    expect_vec(c.direction, {1, 0, 0});
}

TEST_F(BuildCamera, ProjectionsKeepTheirAnglesAndFocalBlurIsUnsupported) {
    scene::Scene s = run("camera { fisheye angle 200 }");
    EXPECT_EQ(s.camera.type, scene::CameraType::Fisheye);
    EXPECT_DOUBLE_EQ(s.camera.angle, 200);  // not folded into direction
    EXPECT_NEAR(glm::length(s.camera.direction), 1, 1e-12);
    EXPECT_TRUE(s.unsupported.empty());
    EXPECT_DOUBLE_EQ(run("camera { ultra_wide_angle }").camera.angle, 90);
    const scene::Camera sph = run("camera { spherical }").camera;
    EXPECT_DOUBLE_EQ(sph.angle, 360);
    EXPECT_DOUBLE_EQ(sph.vertical_angle, 180);
    EXPECT_DOUBLE_EQ(run("camera { spherical angle 120 }").camera.vertical_angle, 60);
    EXPECT_DOUBLE_EQ(run("camera { spherical angle 120, 30 }").camera.vertical_angle, 30);
    const scene::Camera cyl = run("camera { cylinder 3.7 }").camera;
    EXPECT_EQ(cyl.type, scene::CameraType::Cylinder);
    EXPECT_EQ(cyl.cylinder_type, 3);  // truncated
    EXPECT_NE(error_of("camera { cylinder 5 }").find("cylinder camera type must be 1, 2, 3 or 4"),
              std::string::npos);
    EXPECT_NE(error_of("camera { cylinder 1 angle -10 }").find("must not be negative"),
              std::string::npos);
    EXPECT_TRUE(run("camera { normal { bumps 0.5 } }").camera.normal);
}

TEST_F(BuildCamera, FocalBlurSettings) {
    const scene::Camera c =
        run("camera { location -5*z look_at 0 aperture 0.5 focal_point <0,0,3> blur_samples 20 }")
            .camera;
    ASSERT_TRUE(c.blur);
    EXPECT_DOUBLE_EQ(c.blur->aperture, 0.5);
    EXPECT_EQ(c.blur->min_samples, 0);  // one number is the maximum
    EXPECT_EQ(c.blur->max_samples, 20);
    EXPECT_DOUBLE_EQ(c.blur->focal_distance, 8);
    EXPECT_DOUBLE_EQ(c.blur->confidence, 0.9);
    EXPECT_DOUBLE_EQ(c.blur->variance, 1e-4);
    const scene::Camera d =
        run("camera { direction 2*z aperture 1 blur_samples 4, 30 confidence 0.5 variance 0.01 }")
            .camera;
    ASSERT_TRUE(d.blur);
    EXPECT_EQ(d.blur->min_samples, 4);
    EXPECT_EQ(d.blur->max_samples, 30);
    EXPECT_DOUBLE_EQ(d.blur->focal_distance, 2);  // no focal_point: |direction|
    EXPECT_DOUBLE_EQ(d.blur->confidence, 0.5);
    EXPECT_DOUBLE_EQ(d.blur->variance, 0.01);
    // Off without samples or with aperture 0, as in POV-Ray.
    EXPECT_FALSE(run("camera { aperture 1 }").camera.blur);
    EXPECT_FALSE(run("camera { aperture 0 blur_samples 10 }").camera.blur);
    EXPECT_TRUE(run("camera { aperture 0.5 blur_samples 20 }").unsupported.empty());
    EXPECT_NE(error_of("camera { aperture 1 blur_samples 9, 3 }").find("must not be larger"),
              std::string::npos);
    for (const char* bad : {"0", "-1", "0, 4", "1e9"})
        EXPECT_NE(error_of(std::string("camera { aperture 1 blur_samples ") + bad + " }")
                      .find("focal blur samples"),
                  std::string::npos)
            << bad;
    EXPECT_EQ(run("camera { aperture 1 blur_samples 3.7 }").camera.blur->max_samples, 3);
    // A declared camera's focal blur carries over to a copy.
    EXPECT_TRUE(run("#declare C = camera { aperture 1 blur_samples 7 }\ncamera { C }").camera.blur);
}

TEST_F(BuildCamera, BadAngleIsAnError) {
    EXPECT_EQ(error_of("camera { angle 200 }"),
              "t.pov:1:10: error: camera angle must be between 0 and 180 degrees");
}

using BuildLight = BuildTest;

TEST_F(BuildLight, PointLightColourAndLocation) {
    scene::Scene s = run("light_source { <1,2,3>, rgb <1,0.5,0> }");
    ASSERT_EQ(s.lights.size(), 1u);
    expect_vec(s.lights[0].position, {1, 2, 3});
    expect_vec(s.lights[0].colour, {1, 0.5, 0});
    EXPECT_EQ(s.lights[0].loc.line, 1u);
}

TEST_F(BuildLight, SpotlightModifiersAndTransforms) {
    scene::Light l = run("light_source { 0, 1 spotlight point_at x radius 10 falloff 20 "
                         "tightness 5 fade_distance 3 fade_power 2 shadowless translate y }")
                         .lights[0];
    EXPECT_EQ(l.type, scene::LightType::Spot);
    expect_vec(l.position, {0, 1, 0});
    expect_vec(l.point_at, {1, 1, 0});
    EXPECT_DOUBLE_EQ(l.radius, 10);
    EXPECT_DOUBLE_EQ(l.falloff, 20);
    EXPECT_DOUBLE_EQ(l.tightness, 5);
    EXPECT_DOUBLE_EQ(l.fade_distance, 3);
    EXPECT_TRUE(l.shadowless);
}

TEST_F(BuildLight, AreaLightAxesRotate) {
    scene::Light l = run("light_source { 0, 1 area_light x*2, z*2, 3, 5 adaptive 1 jitter "
                         "circular orient area_illumination rotate z*90 }")
                         .lights[0];
    ASSERT_TRUE(l.area.has_value());
    expect_vec(l.area->axis1, {0, 2, 0});
    EXPECT_EQ(l.area->size2, 5);
    EXPECT_EQ(l.area->adaptive, 1);
    EXPECT_TRUE(l.area->jitter && l.area->circular && l.area->orient);
    EXPECT_TRUE(l.area_illumination);
}

TEST_F(BuildLight, LooksLikeMovedToLightAndNoShadow) {
    scene::Light l = run("light_source { <0,5,0>, 1 looks_like { sphere { 0, 0.5 } } translate x }")
                         .lights[0];
    ASSERT_TRUE(l.looks_like);
    EXPECT_TRUE(l.looks_like->no_shadow);
    expect_vec(l.looks_like->transform.point({0, 0, 0}), {1, 5, 0});
}

TEST_F(BuildLight, CylinderAndParallel) {
    scene::Light l = run("light_source { 0, 1 cylinder parallel point_at y }").lights[0];
    EXPECT_EQ(l.type, scene::LightType::Cylinder);
    EXPECT_TRUE(l.parallel);
    EXPECT_DOUBLE_EQ(l.radius, 0.75);
}

TEST_F(BuildLight, LightsInsideCsgAreSceneLightsMovedWithIt) {
    const scene::Scene s = run(
        "#declare Lamp = union { light_source { <1,0,0>, 1 } sphere { 0, 1 } translate y }\n"
        "object { Lamp translate z }\n"
        "merge { union { light_source { 0, rgb <1,0,0> } rotate z*90 } translate x*5 }\n"
        "#declare Unused = union { light_source { 0, 1 } }");
    ASSERT_EQ(s.lights.size(), 2u);
    expect_vec(s.lights[0].position, {1, 1, 1});
    expect_vec(s.lights[1].position, {5, 0, 0});
    expect_vec(s.lights[1].colour, {1, 0, 0});
    EXPECT_TRUE(s.unsupported.empty());
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_EQ(std::get<scene::Csg>(s.objects[0]->shape).children.size(), 1u);
}

TEST_F(BuildLight, ProjectedThroughMovesWithTheLight) {
    const scene::Light l =
        run("light_source { 0, 1 projected_through { sphere { y, 1 } } translate x }").lights[0];
    ASSERT_TRUE(l.projected_through);
    expect_vec(l.projected_through->transform.point({0, 1, 0}), {1, 1, 0});
}

TEST_F(BuildLight, Errors) {
    EXPECT_EQ(error_of("light_source { 0, 1 jitter }"),
              "no error");
    EXPECT_EQ(error_of("light_source { 0, 1 area_light x, y, 0, 1 }"),
              "t.pov:1:21: error: area_light sizes must be at least 1");
}

}  // namespace
}  // namespace lumen::interp::testing

namespace lumen::interp::testing {
namespace {

using BuildCameraErrors = BuildTest;

TEST_F(BuildCameraErrors, DegenerateVectorsAreErrors) {
    EXPECT_EQ(error_of("camera { direction 0 }"),
              "t.pov:1:10: error: camera direction is a zero vector");
    EXPECT_EQ(error_of("camera { location y look_at y }"),
              "t.pov:1:1: error: camera look_at equals its location");
}

TEST_F(BuildCameraErrors, VectorsThatDoNotSpanSpaceAreErrors) {
    EXPECT_EQ(error_of("camera { direction z up z right x }"),
              "t.pov:1:22: error: camera up is parallel to the camera direction");
    EXPECT_EQ(error_of("camera { direction z up y right -2*z }"),
              "t.pov:1:27: error: camera right is parallel to the camera direction");
    EXPECT_EQ(error_of("camera { up y right 3*y }"),
              "t.pov:1:10: error: camera up is parallel to camera right");
    EXPECT_EQ(error_of("camera { right 0 }"), "t.pov:1:10: error: camera right is a zero vector");
    EXPECT_EQ(error_of("camera { up 0 }"), "t.pov:1:10: error: camera up is a zero vector");
    // look_at along the sky keeps right; right along the view leaves nothing to form up.
    EXPECT_EQ(error_of("camera { right z location 0 look_at y }"), "no error");
    EXPECT_EQ(error_of("camera { right y location 0 look_at y }"),
              "t.pov:1:10: error: camera right is parallel to the camera direction");
    EXPECT_EQ(error_of("camera { location <0,1,-5> look_at 0 }"), "no error");
    EXPECT_EQ(error_of("camera { orthographic direction z up y right x }"), "no error");
}

}  // namespace
}  // namespace lumen::interp::testing
