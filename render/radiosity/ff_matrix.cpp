// Form factor matrix builders.
#include "render/radiosity/ff_matrix.hpp"

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

FormFactorMatrix ray_cast_matrix(const std::vector<Patch>& patches, int rays_per_patch,
                                 uint64_t seed, bool symmetrise_pairs) {
    FormFactorMatrix F(patches.size());
    for (size_t i = 0; i < patches.size(); ++i) {
        const auto row = ray_cast_row(patches, i, rays_per_patch, seed + 7919 * i);
        std::copy(row.begin(), row.end(), F.f.begin() + i * F.n);
    }
    if (symmetrise_pairs) symmetrise(F, patches);
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
