#include "render/polynomial.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace lumen::render {
namespace {

// Coefficients (lowest first) of prod (t - r_i).
std::vector<double> from_roots(const std::vector<double>& roots) {
    std::vector<double> c{1};
    for (double r : roots) {
        std::vector<double> next(c.size() + 1, 0);
        for (size_t i = 0; i < c.size(); ++i) {
            next[i + 1] += c[i];
            next[i] -= r * c[i];
        }
        c = next;
    }
    return c;
}

TEST(Polynomial, QuadraticAvoidsCancellation) {
    double r[2];
    // t^2 - 1e8 t + 1 = 0: roots 1e-8 and 1e8; the naive formula loses the small one.
    ASSERT_EQ(solve_quadratic(1, -0.5e8, 1, r), 2);
    EXPECT_NEAR(r[0], 1e-8, 1e-20);
    EXPECT_NEAR(r[1], 1e8, 1e-6);
    EXPECT_EQ(solve_quadratic(1, 0, 1, r), 0);   // no real roots
    EXPECT_EQ(solve_quadratic(0, 1, -4, r), 1);  // linear: 2t - 4
    EXPECT_DOUBLE_EQ(r[0], 2);
    EXPECT_EQ(solve_quadratic(0, 0, 1, r), 0);
}

TEST(Polynomial, QuarticKnownRoots) {
    std::vector<double> roots{-3.5, 0.25, 1.0, 7.0};
    auto c = from_roots(roots);
    double found[4];
    int n = solve_polynomial_in(c.data(), 4, -10, 10, found);
    ASSERT_EQ(n, 4);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(found[i], roots[i], 1e-12);
    // Only the roots in the interval.
    n = solve_polynomial_in(c.data(), 4, 0, 2, found);
    ASSERT_EQ(n, 2);
    EXPECT_NEAR(found[0], 0.25, 1e-12);
    EXPECT_NEAR(found[1], 1.0, 1e-12);
}

TEST(Polynomial, CloseRootsAreSeparated) {
    std::vector<double> roots{1.0, 1.0 + 1e-6, 2.0, 2.0 + 1e-6};
    auto c = from_roots(roots);
    double found[4];
    int n = solve_polynomial_in(c.data(), 4, 0, 3, found);
    ASSERT_EQ(n, 4);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(found[i], roots[i], 1e-8);  // as conditioned
    EXPECT_LT(found[0], found[1]);
    EXPECT_LT(found[2], found[3]);
}

TEST(Polynomial, DoubleRootNeverGivesNaN) {
    auto c = from_roots({1.0, 1.0, 3.0, 5.0});  // a tangent root at 1
    double found[4];
    int n = solve_polynomial_in(c.data(), 4, -1, 6, found);
    ASSERT_GE(n, 2);
    for (int i = 0; i < n; ++i) EXPECT_TRUE(std::isfinite(found[i]));
    EXPECT_NEAR(found[n - 2], 3.0, 1e-12);
    EXPECT_NEAR(found[n - 1], 5.0, 1e-12);
}

// Every sign change seen by a dense brute-force scan must match a returned root.
// A nearest hit asks for the lowest roots only: they are the full solve's, to the bit.
TEST(Polynomial, TheLowestRootsAloneAreTheFullSolvesFirst) {
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> root(-3, 3), coefficient(-2, 2);
    int several = 0;
    for (int i = 0; i < 20000; ++i) {
        // Quartics through four chosen roots (many roots in range), and random ones.
        double c[5];
        if (i % 2) {
            const double r[4] = {root(rng), root(rng), root(rng), root(rng)};
            double p[5] = {1, 0, 0, 0, 0};  // (t - r0)(t - r1)..., lowest power first
            for (int k = 0; k < 4; ++k) {
                for (int j = k + 1; j > 0; --j) p[j] = p[j - 1] - r[k] * p[j];
                p[0] *= -r[k];
            }
            std::copy(p, p + 5, c);
        } else {
            for (double& v : c) v = coefficient(rng);
        }
        const double lo = -2.5, hi = 2.8;
        double all[8], first[8];
        const int n = solve_polynomial_in(c, 4, lo, hi, all);
        for (int max : {1, 2, 3}) {
            const int m = solve_polynomial_in(c, 4, lo, hi, first, max);
            ASSERT_EQ(m, std::min(n, max)) << i;
            for (int k = 0; k < m; ++k) ASSERT_EQ(first[k], all[k]) << i << " root " << k;
        }
        several += n >= 2;
    }
    EXPECT_GT(several, 4000);
}

TEST(Polynomial, RootCountIsTheFullSolvesCount) {
    // count_roots_in skips the refinement only: the same brackets, the same count, for every
    // degree the shapes use, with roots at the interval's ends and tangent ones among them.
    std::mt19937 rng(31);
    std::uniform_real_distribution<double> root(-1, 2), coefficient(-2, 2);
    int with_roots = 0;
    for (int i = 0; i < 20000; ++i) {
        const int n = 3 + i % 4;
        std::vector<double> c(n + 1);
        if (i % 3 == 0) {
            std::vector<double> r(n);
            for (double& v : r) v = root(rng);
            if (i % 9 == 0) r[1] = r[0];  // a double root
            if (i % 7 == 0) r[0] = 0;     // a root on the end
            c = from_roots(r);
        } else {
            for (double& v : c) v = coefficient(rng);
        }
        double roots[8];
        const int full = solve_polynomial_in(c.data(), n, 0, 1, roots);
        ASSERT_EQ(count_roots_in(c.data(), n, 0, 1), full) << i;
        with_roots += full > 0;
    }
    EXPECT_GT(with_roots, 5000);
}

TEST(Polynomial, AgreesWithBruteForceScan) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> coef(-10, 10);
    for (int trial = 0; trial < 200; ++trial) {
        double c[5];
        for (double& x : c) x = coef(rng);
        double found[4];
        int n = solve_polynomial_in(c, 4, -5, 5, found);
        std::vector<double> brute;
        const int steps = 20000;
        double prev = eval_poly(c, 4, -5);
        for (int i = 1; i <= steps; ++i) {
            double t = -5 + 10.0 * i / steps;
            double v = eval_poly(c, 4, t);
            if ((v < 0) != (prev < 0)) brute.push_back(t);
            prev = v;
        }
        ASSERT_EQ(size_t(n), brute.size()) << "trial " << trial;
        for (int i = 0; i < n; ++i) {
            EXPECT_NEAR(found[i], brute[i], 10.0 / steps);
            EXPECT_LT(std::abs(eval_poly(c, 4, found[i])), 1e-9);
        }
    }
}

}  // namespace
}  // namespace lumen::render
