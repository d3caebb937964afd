// Progressive refinement (Cohen et al. 1988), i.e. Southwell relaxation: keep B and the
// unshot radiosity ΔB (both start at E); each step shoots the patch with the largest unshot
// power ΔB_i A_i, adding ρ_j F_ji ΔB_i to every B_j and ΔB_j. Invariant:
// E + ρF B − B = ρF ΔB, so max|ΔB| bounds the residual (row sums <= 1, ρ < 1).
#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

#include "render/radiosity/solver.hpp"

namespace lumen::render::radiosity {

namespace {

double luminance(const glm::dvec3& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }
double max_channel(const glm::dvec3& c) { return std::max({c.x, c.y, c.z}); }

class ProgressiveSolver final : public Solver {
public:
    std::string name() const override { return "progressive"; }
    void init(const RadiositySystem& s) override {
        system_ = s;
        B_ = s.emission;
        unshot_ = s.emission;
        // Ambient factor R = 1 / (1 − ρ̄), ρ̄ the area-weighted mean reflectance.
        glm::dvec3 rho_area(0);
        double area = 0;
        for (size_t i = 0; i < s.size(); ++i) {
            rho_area += s.rho[i] * s.area[i];
            area += s.area[i];
        }
        const glm::dvec3 mean = area > 0 ? rho_area / area : glm::dvec3(0);
        reflection_factor_ = 1.0 / glm::max(1.0 - mean, glm::dvec3(1e-6));
        total_area_ = area;
    }
    bool step() override {
        const size_t n = system_.size();
        size_t shooter = n;
        double most = 0;
        for (size_t i = 0; i < n; ++i) {
            const double power = luminance(unshot_[i]) * system_.area[i];
            if (power > most || (shooter == n && max_channel(unshot_[i]) > 0)) {
                most = power;
                shooter = i;
            }
        }
        if (shooter == n) return false;
        const glm::dvec3 shot = unshot_[shooter];
        unshot_[shooter] = glm::dvec3(0);
        for (size_t j = 0; j < n; ++j) {
            const double f = system_.F(j, shooter);
            if (f == 0) continue;
            const glm::dvec3 gain = system_.rho[j] * f * shot;
            B_[j] += gain;
            unshot_[j] += gain;
        }
        return true;
    }
    double residual() const override {
        double worst = 0;
        for (const auto& u : unshot_) worst = std::max(worst, max_channel(glm::abs(u)));
        return worst;
    }
    std::vector<glm::dvec3> radiosity() const override { return B_; }
    std::vector<glm::dvec3> display() const override {
        glm::dvec3 unshot_power(0);
        for (size_t i = 0; i < unshot_.size(); ++i) unshot_power += unshot_[i] * system_.area[i];
        const glm::dvec3 ambient =
            total_area_ > 0 ? reflection_factor_ * unshot_power / total_area_ : glm::dvec3(0);
        std::vector<glm::dvec3> shown = B_;
        for (size_t i = 0; i < shown.size(); ++i) shown[i] += system_.rho[i] * ambient;
        return shown;
    }

private:
    RadiositySystem system_;
    std::vector<glm::dvec3> B_, unshot_;
    glm::dvec3 reflection_factor_{1};
    double total_area_ = 0;
};

}  // namespace

std::unique_ptr<Solver> make_progressive_solver() { return std::make_unique<ProgressiveSolver>(); }

}  // namespace lumen::render::radiosity
