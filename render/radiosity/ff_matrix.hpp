// The dense form factor matrix F (row i: fractions of the energy leaving i that reach each j)
// and the builders for it: analytic (unoccluded), ray-cast (occluded) and hemicube.
#pragma once
#include <cstdint>
#include <vector>

#include "render/radiosity/form_factor.hpp"
#include "render/radiosity/patch.hpp"
#include "render/radiosity/ray_cast.hpp"

namespace lumen::render::radiosity {

struct FormFactorMatrix {
    size_t n = 0;
    std::vector<double> f;  // row-major n x n
    // Standard error of each row sum where F is a Monte Carlo estimate whose rows may exceed
    // 1 by chance (symmetrised ray casting); empty when the row sums are bounded by 1.
    std::vector<double> row_sigma;

    FormFactorMatrix() = default;
    explicit FormFactorMatrix(size_t size) : n(size), f(size * size, 0.0) {}
    double& operator()(size_t i, size_t j) { return f[i * n + j]; }
    double operator()(size_t i, size_t j) const { return f[i * n + j]; }
    double row_sum(size_t i) const;
};

// Lambert area averages for every pair facing each other (no occlusion test: convex
// enclosures and unoccluded scenes only).
FormFactorMatrix analytic_matrix(const std::vector<Patch>& patches,
                                 const QuadratureOptions& q = {});

// Lambert's unoccluded area average times the visible fraction of `samples` stratified
// point pairs (one on each patch), symmetric in i and j so reciprocity holds exactly. Exact
// for unoccluded pairs; no near-field blow-up.
FormFactorMatrix lambert_visibility_matrix(const std::vector<Patch>& patches,
                                           const Visibility& visible, int samples,
                                           uint64_t seed, const QuadratureOptions& q = {});

// Gathered ray-cast rows (patches occlude each other); `symmetrise` replaces each pair by
// the reciprocity-consistent average F_ij = (A_i F_ij + A_j F_ji) / (2 A_i) and records the
// rows' standard errors (a symmetrised row can sum to a little over 1 by chance).
FormFactorMatrix ray_cast_matrix(const std::vector<Patch>& patches, int rays_per_patch,
                                 uint64_t seed, bool symmetrise = true);

// Hemicube rows at the patch centroids.
FormFactorMatrix hemicube_matrix(const std::vector<Patch>& patches, int resolution);

// Makes A_i F_ij = A_j F_ji hold exactly by averaging the two estimates.
void symmetrise(FormFactorMatrix& F, const std::vector<Patch>& patches);

// The form factor matrix of the inside of a sphere: F_ij = A_j / A_total (exact for any
// patching of a true sphere); useful for furnace tests.
FormFactorMatrix sphere_interior_matrix(const std::vector<Patch>& patches);

}  // namespace lumen::render::radiosity
