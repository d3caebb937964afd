#include "render/radiosity/irradiance_gradients.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lumen::render::radiosity {

IrradianceGradients irradiance_gradients(const GatherStrata& s, const glm::dvec3& t,
                                         const glm::dvec3& b) {
    IrradianceGradients g;
    const int m = s.m, n = s.n;
    if (m < 2 || n < 2 || s.L.size() != size_t(m) * n || s.R.size() != s.L.size()) return g;
    const double pi = std::numbers::pi;
    auto L = [&](int i, int j) { return s.L[size_t(i * n + (j + n) % n)]; };
    auto R = [&](int i, int j) { return s.R[size_t(i * n + (j + n) % n)]; };
    glm::dvec3 rot[3] = {glm::dvec3(0), glm::dvec3(0), glm::dvec3(0)};
    glm::dvec3 tr[3] = {glm::dvec3(0), glm::dvec3(0), glm::dvec3(0)};
    for (int j = 0; j < n; ++j) {
        const double phi = 2 * pi * (j + 0.5) / n, phi_lo = 2 * pi * j / n;
        const glm::dvec3 u = std::cos(phi) * t + std::sin(phi) * b;        // u_k
        const glm::dvec3 v = -std::sin(phi) * t + std::cos(phi) * b;       // v_k
        const glm::dvec3 v_lo = -std::sin(phi_lo) * t + std::cos(phi_lo) * b;  // v_k-
        glm::dvec3 sum_rot(0), sum_theta(0), sum_phi(0);
        for (int i = 0; i < m; ++i) {
            const double s2 = (i + 0.5) / m;  // sin^2 of the stratum's centre
            // tan(theta) L (Ward and Heckbert write -tan with the cross product the other
            // way round; the sign here is for G(n') ~ G + (n x n') . rotation, tested).
            sum_rot += std::sqrt(s2 / (1 - s2)) * L(i, j);
            // Across the theta boundary below stratum i (Ward and Heckbert's first term).
            if (i > 0) {
                const double lo2 = double(i) / m;
                const double r = std::min(R(i, j), R(i - 1, j));
                if (r > 0 && std::isfinite(r))
                    sum_theta += std::sqrt(lo2) * (1 - lo2) / r * (L(i, j) - L(i - 1, j));
            }
            // Across the phi boundary before stratum j.
            const double r = std::min(R(i, j), R(i, j - 1));
            if (r > 0 && std::isfinite(r)) {
                const double width = std::sqrt(double(i + 1) / m) - std::sqrt(double(i) / m);
                sum_phi += width / r * (L(i, j) - L(i, j - 1));
            }
        }
        for (int c = 0; c < 3; ++c) {
            rot[c] += v * sum_rot[c];
            tr[c] += u * (2 * pi / n) * sum_theta[c] + v_lo * sum_phi[c];
        }
    }
    // Ward and Heckbert's gradients are of irradiance E = pi G.
    for (int c = 0; c < 3; ++c) {
        g.rotation[c] = rot[c] * (pi / (m * n)) / pi;
        g.translation[c] = tr[c] / pi;
    }
    return g;
}

}  // namespace lumen::render::radiosity
