#include "render/pov_polynomial.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace lumen::render {
namespace {

// Coefficients (HIGHEST power first) of lead * prod (t - r_i).
std::vector<double> from_roots(const std::vector<double>& roots, double lead = 1) {
    std::vector<double> c{lead};
    for (double r : roots) {
        std::vector<double> next(c.size() + 1, 0);
        for (size_t i = 0; i < c.size(); ++i) {
            next[i] += c[i];
            next[i + 1] -= r * c[i];
        }
        c = next;
    }
    return c;
}

std::vector<double> solve(const std::vector<double>& c, bool sturm, double eps = 0) {
    double r[kMaxPolyOrder];
    int n = solve_pov_polynomial(int(c.size()) - 1, c.data(), r, sturm, eps);
    std::vector<double> out(r, r + n);
    std::sort(out.begin(), out.end());
    return out;
}

void expect_roots(const std::vector<double>& got, const std::vector<double>& want, double tol) {
    ASSERT_EQ(got.size(), want.size());
    for (size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(got[i], want[i], tol) << i;
}

TEST(PovPolynomial, ClosedFormsAndSturmAgreeOnSimpleRoots) {
    for (bool sturm : {false, true}) {
        SCOPED_TRACE(sturm);
        expect_roots(solve(from_roots({0.5, 2, 3}), sturm), {0.5, 2, 3}, 1e-9);
        expect_roots(solve(from_roots({0.25, 1, 4, 7}, -2), sturm), {0.25, 1, 4, 7}, 1e-8);
    }
    // Degree 6 always goes through the Sturm search.
    expect_roots(solve(from_roots({0.1, 0.7, 1.5, 2, 3.3, 9}), false), {0.1, 0.7, 1.5, 2, 3.3, 9},
                 1e-8);
}

TEST(PovPolynomial, SturmKeepsOnlyRootsInZeroToMaxDistance) {
    // The closed forms return the negative roots too; the Sturm search never does.
    expect_roots(solve(from_roots({-2, -1, 1, 3}), false), {-2, -1, 1, 3}, 1e-9);
    expect_roots(solve(from_roots({-2, -1, 1, 3}), true), {1, 3}, 1e-9);
    expect_roots(solve(from_roots({-5, -1, 2, 2e7, 4}), false), {2, 4}, 1e-8);
}

TEST(PovPolynomial, LeadingCoefficientsBelowTenToMinusTenAreDropped) {
    // 5e-11 t^3 + (t - 1)(t - 2): solved as the quadratic (an absolute test).
    expect_roots(solve({5e-11, 1, -3, 2}, false), {1, 2}, 1e-12);
    // 2e-10 is kept: the cubic's third root is far out (and negative: closed forms keep it).
    std::vector<double> kept = solve({2e-10, 1, -3, 2}, false);
    ASSERT_FALSE(kept.empty());
    EXPECT_LT(kept.front(), -1e9);
    // Exact zeros ahead count as small too.
    expect_roots(solve({0, 0, 1, -3, 2}, false), {1, 2}, 1e-12);
}

TEST(PovPolynomial, ARootNearZeroIsDividedOutWithEps) {
    // (t - 1e-6)(t - 1)(t - 2): |c3 / c2| ~ 1e-6 < 1e-4, so only the quadratic part is solved.
    std::vector<double> cubic = from_roots({1e-6, 1, 2});
    expect_roots(solve(cubic, false, 1e-4), {1, 2}, 1e-5);
    expect_roots(solve(cubic, false, 0), {1e-6, 1, 2}, 1e-9);
    std::vector<double> quartic = from_roots({1e-6, 1, 2, 3});
    expect_roots(solve(quartic, false, 1e-4), {1, 2, 3}, 1e-5);
    expect_roots(solve(quartic, true, 1e-4), {1, 2, 3}, 1e-5);
    // A root farther out than the tolerance stays.
    expect_roots(solve(from_roots({1e-2, 1, 2}), false, 1e-4), {1e-2, 1, 2}, 1e-9);
}

TEST(PovPolynomial, DoubleRoots) {
    // A tangent quadratic: one root (|disc| < 1e-10).
    expect_roots(solve(from_roots({2, 2}), false), {2}, 1e-12);
    // Two tangencies of a quartic: each double root comes back (twice or once), close.
    for (bool sturm : {false, true}) {
        SCOPED_TRACE(sturm);
        std::vector<double> r = solve(from_roots({1, 1, 3, 3}), sturm);
        ASSERT_FALSE(r.empty());
        for (double x : r) EXPECT_TRUE(std::fabs(x - 1) < 1e-4 || std::fabs(x - 3) < 1e-4) << x;
        EXPECT_NEAR(r.front(), 1, 1e-4);
        EXPECT_NEAR(r.back(), 3, 1e-4);
    }
}

TEST(PovPolynomial, DifficultQuarticsGoToSturm) {
    // Coefficients spanning more than 1e12 (c4 = 1e18): the closed form is not trusted, and
    // the Sturm search returns the positive roots.
    std::vector<double> c = from_roots({1e3, 1e4, 1e5, 1e6});
    EXPECT_TRUE(pov_solver::difficult_coefficients(4, c.data()));
    expect_roots(solve(c, false), {1e3, 1e4, 1e5, 1e6}, 1e-6);
    EXPECT_FALSE(pov_solver::difficult_coefficients(4, from_roots({1, 2, 3, 4}).data()));
    // POV-Ray's quirk: the largest is kept signed, so after a negative one every later
    // coefficient replaces it, and the spread 1 : 1e-13 goes unnoticed.
    const double sane[5] = {1, 1e-13, 0, 0, 1e-13}, quirk[5] = {-1, 1e-13, 0, 0, 1e-13};
    EXPECT_TRUE(pov_solver::difficult_coefficients(4, sane));
    EXPECT_FALSE(pov_solver::difficult_coefficients(4, quirk));
}

TEST(PovPolynomial, SturmFindsRootsTheClosedFormLoses) {
    // Two pairs of close roots: the resolvent's first root leaves the closed form with a
    // negative discriminant and no roots at all; the Sturm sequence separates all four.
    std::vector<double> c = from_roots({10, 10.001, 30, 30.001});
    EXPECT_TRUE(solve(c, false).empty());
    expect_roots(solve(c, true), {10, 10.001, 30, 30.001}, 1e-8);
}

TEST(PovPolynomial, NothingForConstantsOrNoRealRoots) {
    EXPECT_TRUE(solve({0, 0, 0, 5}, false).empty());
    EXPECT_TRUE(solve({1, 0, 1}, false).empty());           // t^2 + 1
    EXPECT_TRUE(solve({1, 0, 2, 0, 1}, false).empty());     // (t^2 + 1)^2
    EXPECT_TRUE(solve({1, 0, 2, 0, 1}, true).empty());
}

}  // namespace
}  // namespace lumen::render
