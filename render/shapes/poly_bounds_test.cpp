// poly bounds: every point outside the proved box is outside the surface (F above the inside
// level), the box is near the surface's true extent, and polynomials that are not provably
// bounded keep an infinite box.
#include <random>

#include <gtest/gtest.h>

#include "render/shapes/poly.hpp"

namespace lumen::render {
namespace {

// The torus (x^2 + y^2 + z^2 + 1.3^2 - 0.5^2)^2 - 4 1.3^2 (x^2 + z^2) written out as terms.
std::vector<PolyTerm> torus() {
    const double a = 1.3 * 1.3 - 0.25, b = 4 * 1.3 * 1.3;
    return {{1, 4, 0, 0}, {2, 2, 2, 0}, {2, 2, 0, 2}, {1, 0, 4, 0}, {2, 0, 2, 2}, {1, 0, 0, 4},
            {2 * a - b, 2, 0, 0}, {2 * a, 0, 2, 0}, {2 * a - b, 0, 0, 2}, {a * a, 0, 0, 0}};
}

double value(const std::vector<PolyTerm>& terms, const glm::dvec3& p) {
    double v = 0;
    for (const PolyTerm& t : terms)
        v += t.c * std::pow(p.x, t.i) * std::pow(p.y, t.j) * std::pow(p.z, t.k);
    return v;
}

TEST(PolyBounds, NothingInsideOutsideTheBox) {
    const std::vector<std::vector<PolyTerm>> shapes = {
        torus(),
        {{1, 6, 0, 0}, {1, 0, 6, 0}, {1, 0, 0, 6}, {-0.4, 0, 0, 0}},            // x^6+y^6+z^6
        {{1, 2, 0, 0}, {4, 0, 2, 0}, {0.5, 0, 0, 2}, {-3, 1, 0, 0}, {-1, 0, 0, 0}},  // ellipsoid
    };
    std::mt19937 rng(3);
    std::normal_distribution<double> g;
    for (const auto& terms : shapes) {
        const Aabb box = poly_bound_box(terms, 1e-4);
        ASSERT_TRUE(box.finite());
        const double r = box.hi.x;
        // Points just outside the box's inscribed sphere... are not enough: take points
        // outside the box itself, in every direction, near and far.
        for (int i = 0; i < 20000; ++i) {
            glm::dvec3 p(g(rng), g(rng), g(rng));
            p *= r / std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)}) *
                 (1 + 1e-6 + std::fabs(g(rng)) * (i % 2 ? 0.01 : 2));
            ASSERT_GT(value(terms, p), 1e-4) << p.x << " " << p.y << " " << p.z;
        }
    }
    // Near the true extent: the torus reaches 1.8, the sextic 0.4^(1/6) 3^(1/3) = 1.239.
    EXPECT_LT(poly_bound_box(torus(), 1e-4).hi.x, 2.3);
    EXPECT_GT(poly_bound_box(torus(), 1e-4).hi.x, 1.8);
    EXPECT_LT(poly_bound_box(shapes[1], 1e-4).hi.x, 1.5);
}

TEST(PolyBounds, UnboundedOrUnprovedStayInfinite) {
    const std::vector<std::vector<PolyTerm>> shapes = {
        {{1, 3, 0, 0}, {1, 0, 1, 0}},                      // odd degree
        {{1, 2, 0, 0}, {1, 0, 2, 0}, {-1, 0, 0, 2}, {-1, 0, 0, 0}},  // hyperboloid
        {{1, 4, 0, 0}, {1, 0, 4, 0}, {-1, 0, 0, 0}},       // x^4 + y^4: a cylinder along z
        {{-1, 2, 0, 0}, {-1, 0, 2, 0}, {-1, 0, 0, 2}, {1, 0, 0, 0}},  // inside is the outside
        {{1e308, 2, 0, 0}, {1e308, 0, 2, 0}, {1e308, 0, 0, 2}, {-1, 0, 0, 0}},  // overflow
    };
    for (const auto& terms : shapes) EXPECT_FALSE(poly_bound_box(terms, 1e-4).finite());
}

TEST(PolyBounds, MakePolyUsesTheBox) {
    scene::Poly p;
    p.order = 4;
    p.coeffs.assign(scene::Poly::term_count(4), 0.0);
    // x^4 + y^4 + z^4 - 1: terms 0 (x^4), 20 (y^4), 30 (z^4), 34 (constant) in POV's order.
    p.coeffs[0] = p.coeffs[20] = p.coeffs[30] = 1;
    p.coeffs[34] = -1;
    const PolyShape s = make_poly(p);
    ASSERT_TRUE(s.valid);
    EXPECT_TRUE(bounds(s).finite());
    EXPECT_LT(bounds(s).hi.x, 1.4);
    EXPECT_GT(bounds(s).hi.x, 1.0);
}

}  // namespace
}  // namespace lumen::render
