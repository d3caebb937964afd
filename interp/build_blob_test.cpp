// blob through the interpreter: both component forms, component modifiers, flags, errors.
#include "interp/build_test_support.hpp"

namespace lumen::interp::testing {
namespace {

using BuildBlob = BuildTest;

TEST_F(BuildBlob, ComponentsInBothForms) {
    auto b = shape_of<scene::Blob>(
        "blob { threshold 0.6 sphere { <1, 2, 3>, 1.5, strength -2 }\n"
        "  cylinder { 0, <0, 2, 0>, 0.5, 3 } component 1.5, 0.8, <4, 0, 0> sturm }");
    EXPECT_DOUBLE_EQ(b.threshold, 0.6);
    ASSERT_EQ(b.components.size(), 3u);
    EXPECT_FALSE(b.components[0].cylinder);
    expect_vec(b.components[0].a, {1, 2, 3});
    EXPECT_DOUBLE_EQ(b.components[0].radius, 1.5);
    EXPECT_DOUBLE_EQ(b.components[0].strength, -2);
    EXPECT_TRUE(b.components[1].cylinder);
    expect_vec(b.components[1].b, {0, 2, 0});
    EXPECT_DOUBLE_EQ(b.components[1].strength, 3);
    // The old form is strength, radius, centre.
    EXPECT_DOUBLE_EQ(b.components[2].strength, 1.5);
    EXPECT_DOUBLE_EQ(b.components[2].radius, 0.8);
    expect_vec(b.components[2].a, {4, 0, 0});
    EXPECT_TRUE(b.sturm);
    EXPECT_TRUE(b.hierarchy);
    EXPECT_DOUBLE_EQ(shape_of<scene::Blob>("blob { sphere { 0, 1, 1 } }").threshold, 1);
    // POV-Ray squares the radius: a negative one is its magnitude.
    EXPECT_DOUBLE_EQ(shape_of<scene::Blob>("blob { sphere { 0, -2, 1 } }").components[0].radius, 2);
}

TEST_F(BuildBlob, ComponentModifiersStayWithTheirComponent) {
    auto o = first_object(
        "blob { sphere { 0, 1, 1 scale 2 pigment { rgb 1 } translate x }\n"
        "  sphere { y, 1, 1 } hierarchy off pigment { rgb 0.5 } translate 3*z }");
    const auto& b = std::get<scene::Blob>(o->shape);
    EXPECT_FALSE(b.hierarchy);
    ASSERT_TRUE(b.components[0].transform);
    // scale 2 then translate x: the centre lands at x = 1; the blob's own move is not in it.
    expect_vec(b.components[0].transform->point({0, 0, 0}), {1, 0, 0});
    expect_vec(b.components[0].transform->point({1, 0, 0}), {3, 0, 0});
    EXPECT_FALSE(b.components[1].transform);
    EXPECT_EQ(b.components[0].texture.size(), 1u);
    EXPECT_TRUE(b.components[1].texture.empty());
    EXPECT_EQ(o->texture.size(), 1u);  // the blob's own
    expect_vec(o->transform.point({0, 0, 0}), {0, 0, 3});
}

TEST_F(BuildBlob, BadInputIsALocatedError) {
    EXPECT_EQ(error_of("blob { threshold 0.5 }"), "t.pov:1:1: error: a blob needs at least one component");
    EXPECT_EQ(error_of("blob { cylinder { x, x, 1, 1 } }"),
              "t.pov:1:8: error: degenerate blob cylinder component: its ends are the same point");
    EXPECT_EQ(error_of("blob { sphere { 0, 1, 1 } translate x sphere { x, 1, 1 } }"),
              "t.pov:1:39: error: a blob's components come before its object modifiers");
    EXPECT_EQ(error_of("blob { sphere { 0, 1, 1 inverse } }"),
              "t.pov:1:25: error: 'inverse' is not a blob sphere component keyword");
    EXPECT_EQ(error_of("blob { sphere { 0, 1 } }"),
              "t.pov:1:20: error: expected a float in blob sphere component, found the end of the block");
}

}  // namespace
}  // namespace lumen::interp::testing
