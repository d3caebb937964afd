// The "big matrix" reference: (I − diag(ρ_c) F) B_c = E_c by LU with partial pivoting, once
// per colour channel. O(n³); the answer is exact up to round-off.
#include <cmath>

#include "base/diagnostics.hpp"
#include "render/radiosity/solver.hpp"

namespace lumen::render::radiosity {

namespace {

// Solves A x = b in place (A row-major n x n, destroyed). Throws on a singular matrix, which
// for radiosity means ρ = 1 in a closed enclosure.
std::vector<double> lu_solve(std::vector<double> A, std::vector<double> b, size_t n) {
    for (size_t k = 0; k < n; ++k) {
        size_t pivot = k;
        for (size_t r = k + 1; r < n; ++r)
            if (std::abs(A[r * n + k]) > std::abs(A[pivot * n + k])) pivot = r;
        if (!(std::abs(A[pivot * n + k]) > 1e-13))
            throw LumenError(SourceLoc{}, "radiosity matrix is singular (a closed enclosure "
                                          "that reflects all light?)");
        if (pivot != k) {
            for (size_t c = 0; c < n; ++c) std::swap(A[k * n + c], A[pivot * n + c]);
            std::swap(b[k], b[pivot]);
        }
        const double inv = 1.0 / A[k * n + k];
        for (size_t r = k + 1; r < n; ++r) {
            const double m = A[r * n + k] * inv;
            if (m == 0) continue;
            for (size_t c = k; c < n; ++c) A[r * n + c] -= m * A[k * n + c];
            b[r] -= m * b[k];
        }
    }
    for (size_t k = n; k-- > 0;) {
        double s = b[k];
        for (size_t c = k + 1; c < n; ++c) s -= A[k * n + c] * b[c];
        b[k] = s / A[k * n + k];
    }
    return b;
}

class LuSolver final : public StoredSystemSolver {
public:
    std::string name() const override { return "LU"; }
    void init(const RadiositySystem& s) override {
        system_ = s;
        const size_t n = s.size();
        B_.assign(n, glm::dvec3(0));
        for (int c = 0; c < 3; ++c) {
            std::vector<double> A(n * n), e(n);
            for (size_t i = 0; i < n; ++i) {
                for (size_t j = 0; j < n; ++j) A[i * n + j] = -s.rho[i][c] * s.F(i, j);
                A[i * n + i] += 1;
                e[i] = s.emission[i][c];
            }
            const auto x = lu_solve(std::move(A), std::move(e), n);
            for (size_t i = 0; i < n; ++i) B_[i][c] = x[i];
        }
        update_residual();
    }
    bool step() override { return false; }
};

}  // namespace

std::unique_ptr<Solver> make_lu_solver() { return std::make_unique<LuSolver>(); }

}  // namespace lumen::render::radiosity
