// poly, cubic, quartic, polynomial, quadric and superellipsoid through the interpreter.
#include "interp/build_test_support.hpp"

namespace lumen::interp::testing {
namespace {

using BuildAlgebraic = BuildTest;

TEST_F(BuildAlgebraic, PolyCubicQuarticReadTheirCoefficients) {
    auto p = shape_of<scene::Poly>("poly { 2, <1,0,0,0, 1,0,0, 1,0, -1> sturm }");
    EXPECT_EQ(p.order, 2);
    ASSERT_EQ(p.coeffs.size(), 10u);
    EXPECT_DOUBLE_EQ(p.coeffs[9], -1);
    EXPECT_TRUE(p.sturm);
    auto c = shape_of<scene::Poly>(
        "cubic { <1,0,0,0,-3,0,0,0,0,0, 0,0,0,0,0,0,0,0,-1,0> }");
    EXPECT_EQ(c.order, 3);
    EXPECT_DOUBLE_EQ(c.coeffs[4], -3);
    EXPECT_FALSE(c.sturm);
    std::string zeros;
    for (int i = 0; i < 33; ++i) zeros += ",0";
    auto q = shape_of<scene::Poly>("#declare Q = quartic { <1" + zeros + ",2> }\nobject { Q sturm }");
    EXPECT_EQ(q.order, 4);
    EXPECT_DOUBLE_EQ(q.coeffs[34], 2);
    EXPECT_TRUE(q.sturm);  // set again on the copy
}

TEST_F(BuildAlgebraic, PolynomialNamedTermsLaterValueWins) {
    auto p = shape_of<scene::Poly>(
        "polynomial { 4, xyz(4,0,0): 1, xyz(0,0,0): -0.5 xyz(2, 1, 1): 3 xyz(2,1,1): 7 }");
    EXPECT_EQ(p.order, 4);
    ASSERT_EQ(p.coeffs.size(), 35u);
    EXPECT_DOUBLE_EQ(p.coeffs[0], 1);
    EXPECT_DOUBLE_EQ(p.coeffs[34], -0.5);
    EXPECT_DOUBLE_EQ(p.coeffs[scene::Poly::term_index(4, 2, 1, 1)], 7);  // x^2 y z
    EXPECT_EQ(scene::Poly::term_index(4, 2, 1, 1), 5u);
    double sum = 0;
    for (double v : p.coeffs) sum += v;
    EXPECT_DOUBLE_EQ(sum, 7.5);  // the rest are 0
}

TEST_F(BuildAlgebraic, BadInputIsALocatedError) {
    EXPECT_EQ(error_of("poly { 4, <1, 2, 3> }"),
              "t.pov:1:11: error: a poly of order 4 needs 35 coefficients, found 3");
    EXPECT_EQ(error_of("poly { 36, <1, 2> }"), "t.pov:1:8: error: poly order must be 2 to 35, not 36");
    EXPECT_EQ(error_of("polynomial { 2, xyz(2, 1, 0): 1 }"),
              "t.pov:1:17: error: the term's powers add up to more than the order 2");
    EXPECT_EQ(error_of("polynomial { 3, xyz(0.5, 0, 0): 1 }"),
              "t.pov:1:17: error: xyz powers must be whole numbers from 0");
    EXPECT_EQ(error_of("superellipsoid { <1, 2, 3> }"),
              "t.pov:1:18: error: superellipsoid needs a 2-D vector <e, n>");
    // Long vectors stay an error outside the coefficient blocks.
    EXPECT_EQ(error_of("#declare V = <1, 2, 3, 4, 5, 6>;"),
              "t.pov:1:14: error: a vector needs 2 to 5 components, found 6");
}

TEST_F(BuildAlgebraic, QuadricAndSuperellipsoid) {
    auto q = shape_of<scene::Quadric>("quadric { <1, 2, 3>, <4, 5, 6>, <7, 8, 9>, 10 }");
    expect_vec(q.square, {1, 2, 3});
    expect_vec(q.mixed, {4, 5, 6});
    expect_vec(q.linear, {7, 8, 9});
    EXPECT_DOUBLE_EQ(q.constant, 10);
    auto s = shape_of<scene::Superellipsoid>("superellipsoid { <0.25, 0.5> }");
    EXPECT_DOUBLE_EQ(s.e, 0.25);
    EXPECT_DOUBLE_EQ(s.n, 0.5);
}

TEST_F(BuildAlgebraic, OvusRadiiAsPovRayTakesThem) {
    auto o = shape_of<scene::Ovus>("ovus { 1, 0.6 }");
    EXPECT_DOUBLE_EQ(o.bottom, 1);
    EXPECT_DOUBLE_EQ(o.top, 0.6);
    EXPECT_EQ(error_of("ovus { -1, 0.5 }"), "t.pov:1:8: error: both ovus radii must be positive");
    // A top radius of twice the bottom one or more is the sphere it would be (POV warns).
    auto s = shape_of<scene::Sphere>("ovus { 0.5, 1 }");
    expect_vec(s.center, {0, 0.5, 0});
    EXPECT_DOUBLE_EQ(s.radius, 1);
    EXPECT_EQ(warnings.size(), 1u);
}

}  // namespace
}  // namespace lumen::interp::testing
