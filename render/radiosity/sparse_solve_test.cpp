// The sparse scene solvers (Gauss-Seidel, progressive shooting along transposed rows) agree
// with LU on the same system, and report when they stop short.
#include <gtest/gtest.h>

#include <random>

#include "render/radiosity/solver.hpp"
#include "render/radiosity/sparse_solve.hpp"

namespace lumen::render::radiosity {
namespace {

// n unknowns, each row a few random columns summing to at most 0.95.
struct Problem {
    VertexFormFactors F;
    std::vector<glm::dvec3> rho, c;
    std::vector<double> area;
};

Problem random_problem(size_t n, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    Problem p;
    p.F.start.push_back(0);
    for (size_t u = 0; u < n; ++u) {
        const int entries = 1 + int(U(rng) * 8);
        std::vector<uint32_t> cols;
        std::vector<double> w;
        double sum = 0;
        for (int k = 0; k < entries; ++k) {
            uint32_t col = uint32_t(U(rng) * n);
            if (col == u || std::find(cols.begin(), cols.end(), col) != cols.end()) continue;
            cols.push_back(col);
            w.push_back(U(rng));
            sum += w.back();
        }
        const double scale = sum > 0 ? 0.95 * U(rng) / sum : 0;
        std::vector<size_t> order(cols.size());
        for (size_t k = 0; k < order.size(); ++k) order[k] = k;
        std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return cols[a] < cols[b]; });
        for (size_t k : order) {
            p.F.col.push_back(cols[k]);
            p.F.weight.push_back(float(w[k] * scale));
        }
        p.F.start.push_back(uint32_t(p.F.col.size()));
        p.F.env.emplace_back(0);
        p.rho.emplace_back(0.3 + 0.6 * U(rng), 0.3 + 0.6 * U(rng), 0.9 * U(rng));
        p.c.emplace_back(U(rng) < 0.2 ? U(rng) : 0.0, U(rng) * 0.1, 0.0);
        p.area.push_back(0.5 + U(rng));
    }
    return p;
}

std::vector<glm::dvec3> lu_reference(const Problem& p) {
    RadiositySystem s;
    const size_t n = p.c.size();
    s.F = FormFactorMatrix(n);
    for (size_t u = 0; u < n; ++u)
        for (uint32_t k = p.F.start[u]; k < p.F.start[u + 1]; ++k)
            s.F(u, p.F.col[k]) += p.F.weight[k];
    s.rho = p.rho;
    s.emission = p.c;
    s.area = p.area;
    auto lu = make_lu_solver();
    EXPECT_EQ(solve(*lu, s).status, SolveStatus::Converged);
    return lu->radiosity();
}

TEST(SparseSolve, GaussSeidelAndProgressiveAgreeWithLU) {
    const Problem p = random_problem(300, 7);
    const auto reference = lu_reference(p);
    const SparseSolve gs = sparse_gauss_seidel(p.F, p.rho, p.c, 1e-12, 10000);
    const SparseSolve pr = sparse_progressive(p.F, p.rho, p.c, p.area, 1e-12, 10'000'000);
    EXPECT_TRUE(gs.converged);
    EXPECT_TRUE(pr.converged);
    double worst_gs = 0, worst_pr = 0, size = 0;
    for (size_t u = 0; u < reference.size(); ++u)
        for (int k = 0; k < 3; ++k) {
            worst_gs = std::max(worst_gs, std::abs(gs.B[u][k] - reference[u][k]));
            worst_pr = std::max(worst_pr, std::abs(pr.B[u][k] - reference[u][k]));
            size = std::max(size, reference[u][k]);
        }
    EXPECT_GT(size, 0.1);
    EXPECT_LT(worst_gs, 1e-8);
    EXPECT_LT(worst_pr, 1e-8);
}

TEST(SparseSolve, ReportsWhenStoppedShort) {
    const Problem p = random_problem(300, 8);
    EXPECT_FALSE(sparse_gauss_seidel(p.F, p.rho, p.c, 1e-14, 1).converged);
    const SparseSolve pr = sparse_progressive(p.F, p.rho, p.c, p.area, 1e-14, 5);
    EXPECT_FALSE(pr.converged);
    EXPECT_EQ(pr.iterations, 5);
}

}  // namespace
}  // namespace lumen::render::radiosity
