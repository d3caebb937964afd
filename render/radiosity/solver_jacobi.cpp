// Jacobi: B_{k+1} = E + ρ F B_k from B_0 = E. After k sweeps B is the Neumann partial sum
// Σ_{m<=k} (ρF)^m E, i.e. light after k bounces (POV's recursion_limit semantics).
#include "render/radiosity/solver.hpp"

namespace lumen::render::radiosity {

namespace {

class JacobiSolver final : public StoredSystemSolver {
public:
    std::string name() const override { return "Jacobi"; }
    void init(const RadiositySystem& s) override {
        start(s);
    }
    bool step() override {
        const size_t n = system_.size();
        std::vector<glm::dvec3> next(n);
        for (size_t i = 0; i < n; ++i) {
            glm::dvec3 gathered(0);
            for (size_t j = 0; j < n; ++j) gathered += system_.F(i, j) * B_[j];
            next[i] = system_.emission[i] + system_.rho[i] * gathered;
        }
        B_ = std::move(next);
        update_residual();
        return true;
    }
};

}  // namespace

std::unique_ptr<Solver> make_jacobi_solver() { return std::make_unique<JacobiSolver>(); }

}  // namespace lumen::render::radiosity
