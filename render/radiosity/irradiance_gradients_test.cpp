// Irradiance gradients from synthetic strata: against finite differences of G for a sky whose
// radiance is linear in the direction (rotation) and for a half-bright ceiling (translation).
#include <cmath>
#include <functional>
#include <numbers>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "render/radiosity/irradiance_gradients.hpp"
#include "render/radiosity/ray_cast.hpp"

namespace lumen::render::radiosity {
namespace {

using Field = std::function<void(const glm::dvec3& p, const glm::dvec3& d, glm::dvec3& L, double& R)>;

// Strata at their centres about n at p (the gather's layout), and G their mean.
GatherStrata strata_at(const Field& f, const glm::dvec3& p, const glm::dvec3& n, int cells,
                       glm::dvec3& G) {
    glm::dvec3 t, b;
    tangent_frame(n, t, b);
    GatherStrata s{cells, cells, {}, {}};
    G = glm::dvec3(0);
    for (int i = 0; i < cells; ++i)
        for (int j = 0; j < cells; ++j) {
            const double u1 = (i + 0.5) / cells, phi = 2 * std::numbers::pi * (j + 0.5) / cells;
            const double r = std::sqrt(u1), z = std::sqrt(1 - u1);
            const glm::dvec3 d = r * std::cos(phi) * t + r * std::sin(phi) * b + z * n;
            glm::dvec3 L;
            double R;
            f(p, d, L, R);
            s.L.push_back(L);
            s.R.push_back(R);
            G += L / double(cells * cells);
        }
    return s;
}

TEST(IrradianceGradients, RotationFollowsALinearSky) {
    // L(d) = 1 + a.d: G(n) = 1 + (2/3) a.n, so turning n by delta changes G by (2/3) a.delta.
    const glm::dvec3 a(0.3, -0.2, 0.1);
    const Field sky = [&](const glm::dvec3&, const glm::dvec3& d, glm::dvec3& L, double& R) {
        L = glm::dvec3(1 + glm::dot(a, d));
        R = INFINITY;
    };
    const glm::dvec3 n = glm::normalize(glm::dvec3(0.2, 0.3, 1));
    glm::dvec3 G, t, b;
    tangent_frame(n, t, b);
    const IrradianceGradients g = irradiance_gradients(strata_at(sky, {}, n, 32, G), t, b);
    for (const glm::dvec3& delta : {1e-3 * t, 1e-3 * b}) {
        const double predicted = glm::dot(glm::cross(n, n + delta), g.rotation[0]);
        const double expected = 2.0 / 3 * glm::dot(a, delta);
        // Stratum centres under-weight tan(theta) near the horizon: about 8% at 32 x 32.
        EXPECT_NEAR(predicted, expected, 0.1 * std::fabs(expected));
    }
    // A sky at infinity gives no translation gradient.
    EXPECT_EQ(g.translation[0], glm::dvec3(0));
}

TEST(IrradianceGradients, TranslationFollowsAHalfBrightCeiling) {
    // A ceiling at height 1 over the point, bright where x > 0: moving along x changes G.
    const Field ceiling = [](const glm::dvec3& p, const glm::dvec3& d, glm::dvec3& L, double& R) {
        R = (1 - p.z) / d.z;
        L = glm::dvec3((p + R * d).x > 0 ? 1.0 : 0.0, 0, 0);
    };
    const glm::dvec3 n(0, 0, 1);
    glm::dvec3 G, Gl, Gr, t, b;
    tangent_frame(n, t, b);
    const IrradianceGradients g = irradiance_gradients(strata_at(ceiling, {}, n, 64, G), t, b);
    const double h = 0.02;
    strata_at(ceiling, {-h, 0, 0}, n, 256, Gl);
    strata_at(ceiling, {h, 0, 0}, n, 256, Gr);
    const double finite = (Gr.x - Gl.x) / (2 * h);
    ASSERT_GT(finite, 0.3);  // the configuration does vary
    EXPECT_NEAR(g.translation[0].x, finite, 0.1 * finite);
    EXPECT_NEAR(g.translation[0].y, 0, 0.05 * finite);
    EXPECT_NEAR(G.x, 0.5, 0.01);
}

TEST(IrradianceGradients, TooFewStrataGiveNone) {
    GatherStrata s{1, 1, {glm::dvec3(1)}, {1.0}};
    const IrradianceGradients g = irradiance_gradients(s, {1, 0, 0}, {0, 1, 0});
    EXPECT_EQ(g.translation[0], glm::dvec3(0));
    EXPECT_EQ(g.rotation[0], glm::dvec3(0));
}

}  // namespace
}  // namespace lumen::render::radiosity
