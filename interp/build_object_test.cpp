// Shapes, CSG and object modifiers through the whole interpreter.
#include "interp/build_test_support.hpp"

namespace lumen::interp::testing {
namespace {

using BuildObject = BuildTest;

TEST_F(BuildObject, SphereKeepsCentreRadiusAndLocation) {
    scene::ObjectPtr o = first_object("\n  sphere { <1,2,3>, 4 }");
    const auto& s = std::get<scene::Sphere>(o->shape);
    expect_vec(s.center, {1, 2, 3});
    EXPECT_DOUBLE_EQ(s.radius, 4);
    EXPECT_EQ(o->loc.line, 2u);
    EXPECT_EQ(o->loc.column, 3u);
}

TEST_F(BuildObject, PlaneNormalNormalisedDistanceNotDivided) {
    auto p = shape_of<scene::Plane>("plane { <0,2,0>, 3 }");
    expect_vec(p.normal, {0, 1, 0});
    EXPECT_DOUBLE_EQ(p.distance, 3);
}

TEST_F(BuildObject, BoxCornersReordered) {
    auto b = shape_of<scene::Box>("box { <1,-2,3>, <-1,2,-3> }");
    expect_vec(b.min, {-1, -2, -3});
    expect_vec(b.max, {1, 2, 3});
}

TEST_F(BuildObject, CylinderConeOpenAndTorusSturm) {
    auto c = shape_of<scene::Cylinder>("cylinder { 0, y*2, 0.5 open }");
    EXPECT_TRUE(c.open);
    expect_vec(c.cap, {0, 2, 0});
    auto k = shape_of<scene::Cone>("cone { 0, 1, y, 0 }");
    EXPECT_FALSE(k.open);
    EXPECT_DOUBLE_EQ(k.base_radius, 1);
    auto t = shape_of<scene::Torus>("torus { 2, 0.5 sturm }");
    EXPECT_TRUE(t.sturm);
    EXPECT_DOUBLE_EQ(t.major, 2);
}

TEST_F(BuildObject, DiscWithHole) {
    auto d = shape_of<scene::Disc>("disc { 0, z*3, 2, 1 }");
    expect_vec(d.normal, {0, 0, 1});
    EXPECT_DOUBLE_EQ(d.hole, 1);
}

TEST_F(BuildObject, SmoothTriangleNormalsNormalised) {
    auto t = shape_of<scene::Triangle>(
        "smooth_triangle { <0,0,0>, <0,0,-2>, <1,0,0>, <0,0,-3>, <0,1,0>, <0,0,-1> }");
    EXPECT_TRUE(t.smooth);
    expect_vec(t.n[0], {0, 0, -1});
    expect_vec(t.n[1], {0, 0, -1});
}

TEST_F(BuildObject, PolygonClosesSubPolygonsAndWarnsWhenOpen) {
    auto p = shape_of<scene::Polygon>("polygon { 4, <0,0>, <1,0>, <1,1>, <0,0> }");
    EXPECT_EQ(p.points.size(), 4u);
    EXPECT_TRUE(warnings.empty());
    auto q = shape_of<scene::Polygon>("polygon { 3, <0,0>, <1,0>, <1,1> }");
    ASSERT_EQ(q.points.size(), 4u);
    expect_vec(q.points[3], {0, 0, 0});
    EXPECT_FALSE(warnings.empty());
}

TEST_F(BuildObject, TransformsComposeInOrder) {
    scene::ObjectPtr o = first_object("sphere { 0, 1 scale 2 rotate z*90 translate x }");
    expect_vec(o->transform.point({1, 0, 0}), {1, 2, 0});  // scale, then +x -> +y, then +x
    expect_vec(o->transform.inv_point({1, 2, 0}), {1, 0, 0});
}

TEST_F(BuildObject, RotateIsXThenYThenZ) {
    scene::ObjectPtr o = first_object("sphere { 0, 1 rotate <90, 90, 0> }");
    // +y -> +z (x rotation), then +z -> +x (y rotation)
    expect_vec(o->transform.point({0, 1, 0}), {1, 0, 0});
}

TEST_F(BuildObject, MatrixRowsActOnRowVectors) {
    scene::ObjectPtr o = first_object("sphere { 0, 1 matrix <1,0,0, 0,1,0, 0,0,1, 5,6,7> }");
    expect_vec(o->transform.point({0, 0, 0}), {5, 6, 7});
}

TEST_F(BuildObject, ZeroScaleBecomesOneWithWarning) {
    scene::ObjectPtr o = first_object("sphere { 0, 1 scale <2, 0, 1> }");
    expect_vec(o->transform.point({1, 1, 1}), {2, 1, 1});
    EXPECT_FALSE(warnings.empty());
}

TEST_F(BuildObject, TextureBeforeTransformMovesWithObject) {
    scene::ObjectPtr o =
        first_object("sphere { 0, 1 pigment { checker } translate x*5 pigment { checker } }");
    ASSERT_EQ(o->texture.size(), 1u);
    // The second pigment block edits the first, which moved with the object (POV-Ray 3.7 does
    // the same: checked on a render with povray).
    expect_vec(o->texture[0]->pigment->pattern.steps.composed_transform().point({0, 0, 0}), {5, 0, 0});
    scene::ObjectPtr q = first_object(
        "#declare P = pigment { checker }\n"
        "sphere { 0, 1 pigment { checker } translate x*5 pigment { P } }");
    // A block that starts from a declared pigment replaces the one there.
    EXPECT_TRUE(q->texture[0]->pigment->pattern.steps.composed_transform().is_identity());
    scene::ObjectPtr p = first_object("sphere { 0, 1 pigment { checker } translate x*5 }");
    expect_vec(p->texture[0]->pigment->pattern.steps.composed_transform().point({0, 0, 0}), {5, 0, 0});
}

TEST_F(BuildObject, FlagsAndModifiers) {
    scene::ObjectPtr o = first_object(
        "sphere { 0, 1 hollow no_shadow no_image no_reflection double_illuminate inverse }");
    EXPECT_TRUE(o->hollow);
    EXPECT_TRUE(o->no_shadow);
    EXPECT_TRUE(o->no_image);
    EXPECT_TRUE(o->no_reflection);
    EXPECT_TRUE(o->double_illuminate);
    EXPECT_TRUE(o->inverse);
    EXPECT_FALSE(first_object("sphere { 0, 1 hollow off }")->hollow);
}

TEST_F(BuildObject, ObjectIdentCopiesAndModifies) {
    scene::Scene s = run("#declare S = sphere { 0, 1 }\nobject { S translate y }\nobject { S }");
    ASSERT_EQ(s.objects.size(), 2u);
    expect_vec(s.objects[0]->transform.point({0, 0, 0}), {0, 1, 0});
    EXPECT_TRUE(s.objects[1]->transform.is_identity());
    EXPECT_EQ(s.objects[0]->loc.line, 2u);
}

TEST_F(BuildObject, CsgChildrenInheritByKeepingNoTexture) {
    scene::ObjectPtr o = first_object(
        "difference { box { -1, 1 } sphere { 0, 1.2 } pigment { rgb 1 } translate y }");
    const auto& csg = std::get<scene::Csg>(o->shape);
    EXPECT_EQ(csg.op, scene::CsgOp::Difference);
    ASSERT_EQ(csg.children.size(), 2u);
    EXPECT_TRUE(csg.children[0]->texture.empty());
    EXPECT_TRUE(csg.children[0]->transform.is_identity());  // relative to the CSG
    ASSERT_EQ(o->texture.size(), 1u);
}

TEST_F(BuildObject, CsgTransformMovesChildTextures) {
    scene::ObjectPtr o = first_object(
        "union { sphere { 0, 1 pigment { checker } } sphere { x, 1 } translate z*3 }");
    const auto& child = *std::get<scene::Csg>(o->shape).children[0];
    expect_vec(child.texture[0]->pigment->pattern.steps.composed_transform().point({0, 0, 0}), {0, 0, 3});
}

TEST_F(BuildObject, LayeredTexturesStack) {
    scene::ObjectPtr o = first_object(
        "sphere { 0, 1 texture { pigment { rgb 1 } } texture { pigment { rgbt 1 } } }");
    ASSERT_EQ(o->texture.size(), 2u);
    EXPECT_DOUBLE_EQ(o->texture[1]->pigment->colour.t, 1);
}

TEST_F(BuildObject, ClippedByIsInWorldSpace) {
    scene::ObjectPtr o = first_object(
        "sphere { 0, 1 clipped_by { plane { y, 0 } } bounded_by { clipped_by } translate x }");
    ASSERT_EQ(o->clipped_by.size(), 1u);
    ASSERT_EQ(o->bounded_by.size(), 1u);
    expect_vec(o->clipped_by[0]->transform.point({0, 0, 0}), {1, 0, 0});
}

TEST_F(BuildObject, SeveralClippedByBlocksAllClip) {
    scene::ObjectPtr o = first_object(
        "sphere { 0, 1 clipped_by { plane { y, 0 } } clipped_by { plane { x, 0 } } }");
    ASSERT_EQ(o->clipped_by.size(), 2u);
    EXPECT_TRUE(std::holds_alternative<scene::Plane>(o->clipped_by[1]->shape));
}

TEST_F(BuildObject, MeshWithPerTriangleTexture) {
    auto m = shape_of<scene::Mesh>(
        "mesh { triangle { 0, x, y texture { pigment { rgb 1 } } } "
        "smooth_triangle { 0, z, x, z, y, z } inside_vector z }");
    EXPECT_EQ(m.faces.size(), 2u);
    EXPECT_EQ(m.textures.size(), 1u);
    EXPECT_EQ(m.faces[0].tex[0], 0);
    EXPECT_EQ(m.faces[1].tex[0], -1);
    EXPECT_EQ(m.faces[1].n[2], 2);
    ASSERT_TRUE(m.inside_vector.has_value());
}

TEST_F(BuildObject, Mesh2IndicesAndTextures) {
    auto m = shape_of<scene::Mesh>(
        "mesh2 { vertex_vectors { 4, 0, x, y, z } normal_vectors { 1, y } "
        "texture_list { 2, texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } } "
        "face_indices { 2, <0,1,2>, 1, <1,2,3>, 0, 1, 1 } normal_indices { 2, <0,0,0>, <0,0,0> } }");
    ASSERT_EQ(m.faces.size(), 2u);
    EXPECT_EQ(m.faces[0].tex, (std::array<int, 3>{1, 1, 1}));
    EXPECT_EQ(m.faces[1].tex, (std::array<int, 3>{0, 1, 1}));
    EXPECT_EQ(m.faces[1].n, (std::array<int, 3>{0, 0, 0}));
}

// Copies of a declared mesh share its vertices and faces (POV-Ray keeps one copy too), and a
// copy that moves its per-triangle textures gets textures of its own.
TEST_F(BuildObject, MeshCopiesShareTheirBulk) {
    scene::Scene s = run(
        "#declare M = mesh { triangle { 0, x, y texture { pigment { rgb 1 } } } triangle { 0, y, z } }\n"
        "mesh { M translate x } object { M } mesh { M }");
    ASSERT_EQ(s.objects.size(), 3u);
    const auto& a = std::get<scene::Mesh>(s.objects[0]->shape);
    for (size_t i = 1; i < 3; ++i) {
        const auto& b = std::get<scene::Mesh>(s.objects[i]->shape);
        EXPECT_NE(a.vertices.identity(), nullptr);
        EXPECT_EQ(a.vertices.identity(), b.vertices.identity());
        EXPECT_EQ(a.faces.identity(), b.faces.identity());
    }
    const auto& kept1 = std::get<scene::Mesh>(s.objects[1]->shape).textures;
    const auto& kept2 = std::get<scene::Mesh>(s.objects[2]->shape).textures;
    EXPECT_EQ(kept1.identity(), kept2.identity());
    EXPECT_NE(a.textures.identity(), kept2.identity());
    auto placed_x = [](const scene::SharedVector<scene::LayeredTexture>& t) {
        return t[0][0]->pattern.steps.composed_transform().point({0, 0, 0}).x;
    };
    EXPECT_DOUBLE_EQ(placed_x(a.textures), 1);  // the moved copy's texture moved with it
    EXPECT_DOUBLE_EQ(placed_x(kept2), 0);
}

TEST_F(BuildObject, Mesh2IndexOutOfRangeIsAnError) {
    EXPECT_EQ(error_of("mesh2 { vertex_vectors { 3, 0, x, y } face_indices { 1, <0,1,3> } }"),
              "t.pov:1:57: error: vertex index 3 out of range (there are 3)");
}

TEST_F(BuildObject, Errors) {
    EXPECT_EQ(error_of("sphere { 0, 1 translate \"x\" }"),
              "t.pov:1:25: error: expected a vector after 'translate', found a string");
    EXPECT_EQ(error_of("sphere { 0 }"),
              "t.pov:1:10: error: expected a float in sphere, found the end of the block");
    EXPECT_EQ(error_of("plane { 0, 1 }"), "t.pov:1:9: error: the plane normal is a zero vector");
    EXPECT_EQ(error_of("sphere { 0, 1 phong 1 }"), "t.pov:1:15: error: 'phong' is not a sphere keyword");
    EXPECT_EQ(error_of("cylinder { 0, 1, 1 sturm }"),
              "t.pov:1:20: error: 'sturm' is not a cylinder keyword");
}

TEST_F(BuildObject, UnsupportedShapeIsRecorded) {
    scene::Scene s = run("union { lemon { } sphere { 0, 1 photons { target } } }");
    ASSERT_EQ(s.unsupported.size(), 1u);
    EXPECT_EQ(s.unsupported[0].feature, "lemon");
}

TEST_F(BuildObject, PhotonsBlock) {
    scene::Scene s = run("sphere { 0, 1 photons { target 0.5 refraction on reflection off "
                         "collect off pass_through } }");
    ASSERT_TRUE(s.objects[0]->photons.has_value());
    const scene::ObjectPhotons& p = *s.objects[0]->photons;
    EXPECT_TRUE(p.target);
    EXPECT_DOUBLE_EQ(p.target_mult, 0.5);
    // A pass_through target cannot refract: POV-Ray warns and turns refraction off.
    EXPECT_EQ(p.refraction, scene::PhotonToggle::Off);
    EXPECT_EQ(p.reflection, scene::PhotonToggle::Off);
    EXPECT_FALSE(p.collect);
    EXPECT_TRUE(p.pass_through);
    EXPECT_FALSE(warnings.empty());
    // target 0 (or less) is no target.
    EXPECT_FALSE(run("sphere { 0, 1 photons { target 0 } }").objects[0]->photons->target);
    EXPECT_FALSE(run("sphere { 0, 1 }").objects[0]->photons.has_value());
}

// Each placement of a light_group is a group of its own, with its lights moved along; a light
// in a plain union inside a group lights the whole scene (group 0).
TEST_F(BuildObject, LightGroupsNumberedPerPlacement) {
    scene::Scene s = run(
        "#declare G = light_group { light_source { <1,0,0>, 1 } sphere { 0, 1 } "
        "union { light_source { 0, 1 } sphere { 0, 1 } } global_lights }\n"
        "object { G translate y }\nobject { G }\nsphere { 0, 1 }");
    EXPECT_EQ(s.light_groups, 2u);
    ASSERT_EQ(s.lights.size(), 4u);
    EXPECT_EQ(s.lights[0].group, 1u);
    expect_vec(s.lights[0].position, {1, 1, 0});
    EXPECT_EQ(s.lights[1].group, 0u);
    EXPECT_EQ(s.lights[2].group, 2u);
    ASSERT_EQ(s.objects.size(), 3u);
    for (uint32_t i = 0; i < 2; ++i) {
        const auto& g = std::get<scene::Csg>(s.objects[i]->shape);
        EXPECT_TRUE(g.is_light_group);
        EXPECT_TRUE(g.global_lights);
        EXPECT_EQ(g.light_group, i + 1);
        EXPECT_EQ(g.op, scene::CsgOp::Union);
    }
    EXPECT_EQ(error_of("union { sphere { 0, 1 } global_lights on }"),
              "t.pov:1:25: error: 'global_lights' is not an union keyword");
}

}  // namespace
}  // namespace lumen::interp::testing
