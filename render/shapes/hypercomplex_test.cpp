// The hypercomplex arithmetic julia_fractal iterates with: each step is the algebra's own
// operation (h^2 + c is h times h plus c, 1/h times h is 1, f(h) of a real h is the real f),
// and the complex functions evaluated by POV-Ray's formulas agree with <complex> away from
// their branch cuts.
#include <cmath>
#include <complex>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "render/shapes/hypercomplex.hpp"

namespace lumen::render {
namespace {

using scene::JuliaFunction;

const glm::dvec4 kH{0.3, -0.2, 0.45, 0.1};
const glm::dvec4 kC{0.05, 0.1, -0.2, 0.3};

void expect_near(const glm::dvec4& a, const glm::dvec4& b, double tol = 1e-12) {
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(a[i], b[i], tol) << "component " << i;
}

TEST(Hypercomplex, SqrAndCubeStepSquare) {
    const glm::dvec4 sq = hypercomplex_product(kH, kH) + kC;
    expect_near(hypercomplex_step(JuliaFunction::Sqr, kH, kC, {}), sq);
    // POV-Ray's hypercomplex cube iterates h^2 + c as well.
    expect_near(hypercomplex_step(JuliaFunction::Cube, kH, kC, {}), sq);
}

TEST(Hypercomplex, ProductIsCommutativeWithKSquaredOne) {
    const glm::dvec4 k{0, 0, 0, 1}, i{0, 1, 0, 0}, j{0, 0, 1, 0};
    expect_near(hypercomplex_product(k, k), {1, 0, 0, 0});
    expect_near(hypercomplex_product(i, j), k);
    expect_near(hypercomplex_product(kH, kC), hypercomplex_product(kC, kH));
}

TEST(Hypercomplex, ReciprocalTimesItselfIsOne) {
    const glm::dvec4 r = hypercomplex_step(JuliaFunction::Reciprocal, kH, glm::dvec4(0), {});
    expect_near(hypercomplex_product(r, kH), {1, 0, 0, 0});
    // The chain factor of reciprocal is the derivative -1/h^2.
    expect_near(hypercomplex_chain_factor(JuliaFunction::Reciprocal, kH, {}),
                -hypercomplex_product(r, r));
}

TEST(Hypercomplex, FunctionsOfARealNumberAreTheRealFunctions) {
    const glm::dvec4 h{0.4, 0, 0, 0};
    EXPECT_NEAR(hypercomplex_step(JuliaFunction::Exp, h, glm::dvec4(0), {}).x, std::exp(0.4), 1e-14);
    EXPECT_NEAR(hypercomplex_step(JuliaFunction::Sin, h, glm::dvec4(0), {}).x, std::sin(0.4), 1e-14);
    EXPECT_NEAR(hypercomplex_step(JuliaFunction::Atan, h, glm::dvec4(0), {}).x, std::atan(0.4), 1e-14);
    // The function's value, not its derivative, enters the chain (POV-Ray's rule).
    expect_near(hypercomplex_chain_factor(JuliaFunction::Cos, h, {}),
                {std::cos(0.4), 0, 0, 0});
}

TEST(Hypercomplex, ComplexFunctionsMatchTheStandardOnes) {
    using C = std::complex<double>;
    const C z(0.3, 0.7), e(2, 0.3);
    const struct {
        JuliaFunction fn;
        C want;
    } cases[] = {
        {JuliaFunction::Exp, std::exp(z)},     {JuliaFunction::Ln, std::log(z)},
        {JuliaFunction::Sin, std::sin(z)},     {JuliaFunction::Cos, std::cos(z)},
        {JuliaFunction::Tan, std::tan(z)},     {JuliaFunction::Sinh, std::sinh(z)},
        {JuliaFunction::Cosh, std::cosh(z)},   {JuliaFunction::Tanh, std::tanh(z)},
        {JuliaFunction::Asin, std::asin(z)},   {JuliaFunction::Acos, std::acos(z)},
        {JuliaFunction::Atan, std::atan(z)},   {JuliaFunction::Asinh, std::asinh(z)},
        {JuliaFunction::Acosh, std::acosh(z)}, {JuliaFunction::Atanh, std::atanh(z)},
        {JuliaFunction::Pwr, std::pow(z, e)},  {JuliaFunction::Reciprocal, 1.0 / z},
    };
    for (const auto& c : cases) {
        const C got = julia_complex_function(c.fn, z, e);
        EXPECT_NEAR(got.real(), c.want.real(), 1e-12) << int(c.fn);
        EXPECT_NEAR(got.imag(), c.want.imag(), 1e-12) << int(c.fn);
    }
}

TEST(Hypercomplex, SingularArgumentsStayFinite) {
    // 0 for pwr and ln's neighbours, the null cone for reciprocal, atanh's poles.
    const glm::dvec4 zero(0), cone{0.5, 0, 0, 0.5};
    EXPECT_EQ(hypercomplex_step(JuliaFunction::Pwr, zero, kC, {2, 0}), kC);
    const glm::dvec4 r = hypercomplex_step(JuliaFunction::Reciprocal, cone, glm::dvec4(0), {});
    for (int i = 0; i < 4; ++i) EXPECT_TRUE(std::isfinite(r[i]));
    const std::complex<double> a =
        julia_complex_function(JuliaFunction::Atanh, {1, 0}, {});
    EXPECT_TRUE(std::isfinite(a.real()) && std::isfinite(a.imag()));
}

}  // namespace
}  // namespace lumen::render
