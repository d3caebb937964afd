// sphere_sweep through the interpreter: what POV-Ray 3.7 accepts (probed with povray) and
// the located errors where it refuses.
#include <cstdio>

#include "interp/build_test_support.hpp"

namespace lumen::interp::testing {
namespace {

using BuildSphereSweep = BuildTest;

TEST_F(BuildSphereSweep, SplinesSpheresAndTolerance) {
    auto s = shape_of<scene::SphereSweep>(
        "sphere_sweep { b_spline 4, <0, 0, 0>, 1, <1, 0, 0>, 0.5, <2, 1, 0>, 0.5, <3, 0, 1>, "
        "0.25 tolerance 1e-3 }");
    EXPECT_EQ(s.spline, scene::SweepSpline::BSpline);
    ASSERT_EQ(s.spheres.size(), 4u);
    expect_vec(s.spheres[3].center, {3, 0, 1});
    EXPECT_DOUBLE_EQ(s.spheres[1].radius, 0.5);
    EXPECT_DOUBLE_EQ(s.tolerance, 1e-3);
    // Commas are optional, a float centre is promoted, the count truncated, and any radius
    // taken (POV-Ray squares it); the default tolerance is 1e-6.
    auto l = shape_of<scene::SphereSweep>("sphere_sweep { linear_spline 2.7, 0, -1 <1, 2, 3> 0 }");
    EXPECT_EQ(l.spline, scene::SweepSpline::Linear);
    ASSERT_EQ(l.spheres.size(), 2u);
    expect_vec(l.spheres[0].center, {0, 0, 0});
    EXPECT_DOUBLE_EQ(l.spheres[0].radius, -1);
    EXPECT_DOUBLE_EQ(l.tolerance, 1e-6);
    EXPECT_EQ(shape_of<scene::SphereSweep>(
                  "sphere_sweep { cubic_spline 4, 0, 1, x, 1, y, 1, z, 1 translate x }").spline,
              scene::SweepSpline::Cubic);
}

TEST_F(BuildSphereSweep, BadInputIsALocatedError) {
    EXPECT_EQ(error_of("sphere_sweep { 2, 0, 1, x, 1 }"),
              "t.pov:1:16: error: a sphere_sweep starts with its interpolation type: "
              "linear_spline, b_spline or cubic_spline");
    EXPECT_EQ(error_of("sphere_sweep { quadratic_spline 3, 0, 1, x, 1, y, 1 }"),
              "t.pov:1:16: error: a sphere_sweep starts with its interpolation type: "
              "linear_spline, b_spline or cubic_spline");
    EXPECT_EQ(error_of("sphere_sweep { linear_spline\n 1, 0, 1 }"),
              "t.pov:2:2: error: too few spheres for a sphere_sweep's linear_spline: it needs "
              "at least two");
    EXPECT_EQ(error_of("sphere_sweep { cubic_spline 3, 0, 1, x, 1, y, 1 }"),
              "t.pov:1:29: error: too few spheres for a sphere_sweep's b_spline or "
              "cubic_spline: it needs at least four");
    EXPECT_EQ(error_of("sphere_sweep { b_spline -4 }"),
              "t.pov:1:25: error: too few spheres for a sphere_sweep's b_spline or "
              "cubic_spline: it needs at least four");
    // Fewer spheres than counted: the next item is not the float expected.
    EXPECT_NE(error_of("sphere_sweep { linear_spline 3, 0, 1, x, 1 pigment { rgb 1 } }")
                  .find("t.pov:1:44: error: expected a vector"),
              std::string::npos);
    // Only one spline keyword, and the tolerance before the modifiers, once.
    EXPECT_NE(error_of("sphere_sweep { linear_spline b_spline 4, 0, 1, x, 1, y, 1, z, 1 }")
                  .find("t.pov:1:30: error:"),
              std::string::npos);
    EXPECT_EQ(error_of("sphere_sweep { linear_spline 2, 0, 1, x, 1 pigment { rgb 1 } tolerance 0.1 }"),
              "t.pov:1:62: error: a sphere_sweep's tolerance comes before its object modifiers "
              "(and only once)");
    EXPECT_EQ(error_of("sphere_sweep { linear_spline 2, 0, 1, x, 1 tolerance 0.1 tolerance 0.2 }"),
              "t.pov:1:58: error: a sphere_sweep's tolerance comes before its object modifiers "
              "(and only once)");
    EXPECT_NE(error_of("sphere_sweep { linear_spline 2, 0, 1, x, 1 sturm }").find("t.pov:1:44: error:"),
              std::string::npos);
    EXPECT_EQ(error_of("sphere_sweep { linear_spline 2, <0, 0, 0, 0>, 1, x, 1 }"),
              "t.pov:1:33: error: expected a 3-component vector, found 4 components");
    EXPECT_EQ(error_of("sphere_sweep { linear_spline 2, 0, 1/0, x, 1 }").substr(0, 12), "t.pov:1:36: ");
}

TEST_F(BuildSphereSweep, ExtentsAsPovRay) {
    // min_extent/max_extent printed by povray: the listed spheres' boxes (twice the radius
    // for cubic_spline), a radius's sign kept, so all-negative radii invert the box.
    struct Case {
        const char* sweep;
        glm::dvec3 lo, hi;
    };
    const Case cases[] = {
        {"b_spline 4, <0,0,0>, 1, <1,0,0>,2, <2,3,0>,1,<3,0,0>,0.5", {-1, -2, -2}, {3.5, 4, 2}},
        {"cubic_spline 4, <0,0,0>, 1, <1,0,0>,2, <2,3,0>,1,<3,0,0>,0.5", {-3, -4, -4}, {5, 5, 4}},
        {"linear_spline 2, <0,0,0>, -1, <1,0,0>,-2", {1, 1, 1}, {-1, -1, -1}},
        {"linear_spline 2, <0,0,0>, 1, <1,0,0>,1 scale 2", {-2, -2, -2}, {4, 2, 2}},
    };
    for (const Case& c : cases) {
        char check[400];
        std::snprintf(check, sizeof check,
                      "#declare S = sphere_sweep { %s }\n"
                      "#declare D = vlength(min_extent(S) - <%g, %g, %g>) + "
                      "vlength(max_extent(S) - <%g, %g, %g>);\n"
                      "#if (D > 1e-6) #error concat(\"off by \", str(D, 0, 6)) #end\n",
                      c.sweep, c.lo.x, c.lo.y, c.lo.z, c.hi.x, c.hi.y, c.hi.z);
        EXPECT_EQ(error_of(check), "no error") << c.sweep;
    }
}

}  // namespace
}  // namespace lumen::interp::testing
