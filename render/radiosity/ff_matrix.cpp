// Form factor matrix builders.
#include "render/radiosity/ff_matrix.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include <glm/geometric.hpp>

#include "render/radiosity/hemicube.hpp"
#include "render/radiosity/ray_cast.hpp"

namespace lumen::render::radiosity {

double FormFactorMatrix::row_sum(size_t i) const {
    double s = 0;
    for (size_t j = 0; j < n; ++j) s += f[i * n + j];
    return s;
}

FormFactorMatrix analytic_matrix(const std::vector<Patch>& patches, const QuadratureOptions& q) {
    FormFactorMatrix F(patches.size());
    for (size_t i = 0; i < patches.size(); ++i)
        for (size_t j = 0; j < patches.size(); ++j)
            if (i != j) F(i, j) = patch_to_patch(patches[i], patches[j], q);
    return F;
}

FormFactorMatrix lambert_visibility_matrix(const std::vector<Patch>& patches,
                                           const Visibility& visible, int samples,
                                           uint64_t seed, const QuadratureOptions& q) {
    FormFactorMatrix F(patches.size());
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    const int side = std::max(1, int(std::sqrt(double(std::max(samples, 1)))));
    for (size_t i = 0; i < F.n; ++i)
        for (size_t j = i + 1; j < F.n; ++j) {
            const double fij = patch_to_patch(patches[i], patches[j], q);
            if (fij == 0) continue;
            double seen = 1;
            if (visible && samples > 0) {
                int count = 0;
                for (int k = 0; k < samples; ++k) {
                    const int cell = k % (side * side);
                    const double a = (cell % side + uni(rng)) / side;
                    const double b = (cell / side + uni(rng)) / side;
                    const glm::dvec3 x = sample_point(patches[i], a, b);
                    const glm::dvec3 y = sample_point(patches[j], uni(rng), uni(rng));
                    if (visible(x, y)) ++count;
                }
                seen = double(count) / samples;
            }
            F(i, j) = fij * seen;
            // Reciprocity: A_i F_ij = A_j F_ji.
            F(j, i) = patches[j].area > 0 ? patches[i].area * F(i, j) / patches[j].area : 0;
        }
    return F;
}

FormFactorMatrix ray_cast_matrix(const std::vector<Patch>& patches, int rays_per_patch,
                                 uint64_t seed, bool symmetrise_pairs) {
    FormFactorMatrix F(patches.size());
    for (size_t i = 0; i < patches.size(); ++i) {
        const auto row = ray_cast_row(patches, i, rays_per_patch, seed + 7919 * i);
        std::copy(row.begin(), row.end(), F.f.begin() + i * F.n);
    }
    if (!symmetrise_pairs) return F;  // each row sums to the fraction of rays that hit: <= 1
    // Row i after symmetrising is ½ Σ_j F_ij + ½ Σ_j (A_j/A_i) F_ji, with binomial variances
    // from the independent rows that went into it.
    std::vector<double> sigma(F.n, 0.0);
    for (size_t i = 0; i < F.n; ++i) {
        if (!(patches[i].area > 0)) continue;  // symmetrising zeroes the row
        const double hit = F.row_sum(i);
        double var = hit * (1 - hit);
        for (size_t j = 0; j < F.n; ++j) {
            const double r = patches[j].area / patches[i].area, f = F(j, i);
            var += r * r * f * (1 - f);
        }
        sigma[i] = 0.5 * std::sqrt(std::max(0.0, var) / rays_per_patch);
    }
    symmetrise(F, patches);
    F.row_sigma = std::move(sigma);
    return F;
}

FormFactorMatrix hemicube_matrix(const std::vector<Patch>& patches, int resolution) {
    FormFactorMatrix F(patches.size());
    for (size_t i = 0; i < patches.size(); ++i) {
        const auto row = hemicube_row(patches, i, resolution);
        std::copy(row.begin(), row.end(), F.f.begin() + i * F.n);
    }
    return F;
}

void symmetrise(FormFactorMatrix& F, const std::vector<Patch>& patches) {
    for (size_t i = 0; i < F.n; ++i)
        for (size_t j = i + 1; j < F.n; ++j) {
            const double ai = patches[i].area, aj = patches[j].area;
            if (!(ai > 0) || !(aj > 0)) {
                F(i, j) = F(j, i) = 0;
                continue;
            }
            const double flux = 0.5 * (ai * F(i, j) + aj * F(j, i));
            F(i, j) = flux / ai;
            F(j, i) = flux / aj;
        }
}

FormFactorMatrix sphere_interior_matrix(const std::vector<Patch>& patches) {
    FormFactorMatrix F(patches.size());
    const double total = total_area(patches);
    if (!(total > 0)) return F;
    for (size_t i = 0; i < F.n; ++i)
        for (size_t j = 0; j < F.n; ++j) F(i, j) = patches[j].area / total;
    return F;
}

}  // namespace lumen::render::radiosity
