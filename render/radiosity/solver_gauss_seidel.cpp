// Gauss-Seidel (SOR when omega != 1): sweeps in place, so each patch already sees the
// updated values of the patches before it. Cohen 1986 suggests omega ≈ 1.1.
#include "render/radiosity/solver.hpp"

namespace lumen::render::radiosity {

namespace {

class GaussSeidelSolver final : public StoredSystemSolver {
public:
    explicit GaussSeidelSolver(double omega) : omega_(omega) {}
    std::string name() const override { return omega_ == 1.0 ? "Gauss-Seidel" : "SOR"; }
    void init(const RadiositySystem& s) override {
        start(s);
    }
    bool step() override {
        const size_t n = system_.size();
        for (size_t i = 0; i < n; ++i) {
            glm::dvec3 gathered(0);
            for (size_t j = 0; j < n; ++j)
                if (j != i) gathered += system_.F(i, j) * B_[j];
            // Solve row i for B_i exactly (curved patches have F_ii > 0).
            const double fii = system_.F(i, i);
            glm::dvec3 target = system_.emission[i] + system_.rho[i] * gathered;
            for (int c = 0; c < 3; ++c) {
                const double diag = 1.0 - system_.rho[i][c] * fii;
                // diag <= 0 only for ρ F_ii >= 1 (allow_unstable runs): plain update then.
                target[c] = diag > 1e-12 ? target[c] / diag
                                         : target[c] + system_.rho[i][c] * fii * B_[i][c];
            }
            B_[i] += omega_ * (target - B_[i]);
        }
        update_residual();
        return true;
    }

private:
    double omega_;
};

}  // namespace

std::unique_ptr<Solver> make_gauss_seidel_solver(double omega) {
    return std::make_unique<GaussSeidelSolver>(omega > 0 && omega < 2 ? omega : 1.0);
}

}  // namespace lumen::render::radiosity
