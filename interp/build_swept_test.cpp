// prism, lathe and sor through the interpreter: spline and sweep keywords, flags, the closing
// of linear prisms, and the point lists POV-Ray rejects as located errors (its reasons,
// probed with povray 3.7).
#include "interp/build_test_support.hpp"

namespace lumen::interp::testing {
namespace {

using BuildSwept = BuildTest;

TEST_F(BuildSwept, PrismReadsSplineSweepHeightsAndFlags) {
    auto p = shape_of<scene::Prism>(
        "prism { conic_sweep cubic_spline 1, 0.2, 7, <0,-1>, <1,0>, <0,1>, <-1,0>, <0,-1>, "
        "<1,0>, <0,1> open sturm }");
    EXPECT_EQ(p.spline, scene::SplineKind::Cubic);
    EXPECT_TRUE(p.conic && p.open && p.sturm && p.closed);
    EXPECT_EQ(p.height1, 0.2);  // swapped into order
    EXPECT_EQ(p.height2, 1);
    EXPECT_EQ(p.points.size(), 7u);
    EXPECT_TRUE(warnings.empty());
}

TEST_F(BuildSwept, UnclosedLinearPrismIsClosedWithAWarning) {
    auto p = shape_of<scene::Prism>("prism { 0, 1, 3, <0,0>, <1,0>, <0,1> }");
    ASSERT_EQ(p.points.size(), 4u);
    EXPECT_EQ(p.points.back(), glm::dvec2(0, 0));
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].message.find("not closed"), std::string::npos);
    // A second sub-polygon is closed by its own first point.
    warnings.clear();
    auto two = shape_of<scene::Prism>(
        "prism { 0, 1, 7, <0,0>, <1,0>, <0,1>, <0,0>, <5,5>, <6,5>, <5,6> }");
    EXPECT_EQ(two.points.back(), glm::dvec2(5, 5));
    EXPECT_EQ(warnings.size(), 1u);
}

TEST_F(BuildSwept, UnclosedBezierPrismIsKeptButNeverHit) {
    auto p = shape_of<scene::Prism>(
        "prism { bezier_spline 0, 1, 4, <0,0>, <1,0>, <1,1>, <0,1> }");
    EXPECT_FALSE(p.closed);
    EXPECT_EQ(warnings.size(), 1u);
}

TEST_F(BuildSwept, TooFewPointsAreLocatedErrors) {
    EXPECT_EQ(error_of("prism { 0, 1, 2, <0,0>, <1,0> }"),
              "t.pov:1:15: error: a prism with linear splines must have at least three points");
    EXPECT_EQ(error_of("prism { quadratic_spline 0, 1, 4, <0,0>, <1,0>, <0,1>, <1,0> }"),
              "t.pov:1:32: error: a prism with quadratic splines must have at least five points");
    EXPECT_EQ(error_of("prism { cubic_spline 0, 1, 5, <0,0>, <1,0>, <0,1>, <1,0>, <1,1> }"),
              "t.pov:1:28: error: a prism with cubic splines must have at least six points");
    EXPECT_EQ(error_of("prism { bezier_spline 0, 1, 6, <0,0>, <1,0>, <0,1>, <1,0>, <1,1>, <0,0> }"),
              "t.pov:1:29: error: a prism with Bezier splines must have four points per segment");
    EXPECT_EQ(error_of("lathe { 1, <0,0> }"),
              "t.pov:1:9: error: a lathe with linear splines must have at least two points");
    EXPECT_EQ(error_of("lathe { cubic_spline 3, <0,0>, <1,1>, <1,2> }"),
              "t.pov:1:22: error: a lathe with cubic splines must have at least four points");
    EXPECT_EQ(error_of("sor { 3, <0,0>, <1,1>, <1,2> }"),
              "t.pov:1:7: error: a surface of revolution must have at least four points");
    // A count larger than the points given runs into the modifiers.
    EXPECT_NE(error_of("prism { 0, 1, 4, <0,0>, <1,0>, <0,1> pigment { rgb 1 } }").find("error"),
              std::string::npos);
}

TEST_F(BuildSwept, UnclosedQuadraticPrismIsRejected) {
    // POV-Ray: "Prism not closed" then "Too few points in prism".
    const std::string e =
        error_of("prism { quadratic_spline 0, 1, 5, <0,0>, <1,0>, <0,1>, <0,2>, <1,1> }");
    EXPECT_NE(e.find("t.pov:1:63: error: too few points in prism"), std::string::npos) << e;
    EXPECT_EQ(error_of("prism { quadratic_spline 0, 1, 5, <0,0>, <1,0>, <0,1>, <-1,0>, <1,0> }"),
              "no error");
    // Closed, then points that make no segment: not closed either (measured).
    EXPECT_NE(error_of("prism { cubic_spline 0, 1, 9, <0,-1>, <1,0>, <0,1>, <-1,0>, <0,-1>, "
                       "<1,0>, <0,1>, <5,5>, <6,6> }")
                  .find("too few points in prism"),
              std::string::npos);
}

TEST_F(BuildSwept, SorPointsMustRise) {
    EXPECT_EQ(error_of("sor { 4, <0,0>, <1,1>, <1,1>, <1,3> }"),
              "t.pov:1:24: error: incorrect point in surface of revolution: heights must rise "
              "from the second point on");
    EXPECT_EQ(error_of("sor { 4, <0,0>, <-1,1>, <1,2>, <1,3> }"),
              "t.pov:1:17: error: incorrect point in surface of revolution: negative radius");
    EXPECT_EQ(error_of("sor { 4, <0,0>, <1,1>, <1,2>, <1,1> }"),
              "t.pov:1:31: error: incorrect point in surface of revolution: heights must rise "
              "from the second point on");
    EXPECT_EQ(error_of("sor { 4, <0,0>, <1,0>, <1,2>, <1,3> }"), "no error");  // P0 only steers
    EXPECT_EQ(error_of("sor { 4, <0,0>, <1,1>, <1,2>, <1,2> }"), "no error");  // as sor1.pov
    auto s = shape_of<scene::Sor>("sor { 4, <0,0>, <1,0>, <1,2>, <1,3> open sturm }");
    EXPECT_TRUE(s.open && s.sturm);
}

TEST_F(BuildSwept, LatheTakesSturmButNotOpen) {
    EXPECT_TRUE(shape_of<scene::Lathe>("lathe { bezier_spline 4, <0,0>, <1,0>, <1,1>, <0,1> sturm }").sturm);
    EXPECT_NE(error_of("lathe { 2, <0,0>, <1,1> open }").find("error"), std::string::npos);
}

}  // namespace
}  // namespace lumen::interp::testing
