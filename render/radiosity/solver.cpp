// System assembly, stability checks and the common solve loop.
#include "render/radiosity/solver.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "base/diagnostics.hpp"

namespace lumen::render::radiosity {

RadiositySystem make_system(const std::vector<Patch>& patches, FormFactorMatrix F) {
    RadiositySystem s;
    s.F = std::move(F);
    for (const auto& p : patches) {
        s.rho.push_back(p.rho);
        s.emission.push_back(p.emission);
        s.area.push_back(p.area);
    }
    return s;
}

namespace {

bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

std::string stability_problem(const RadiositySystem& s) {
    const size_t n = s.size();
    std::ostringstream why;
    if (s.rho.size() != n || s.emission.size() != n || s.area.size() != n ||
        s.F.f.size() != n * n)
        return "radiosity system sizes disagree";
    for (size_t i = 0; i < n; ++i) {
        const glm::dvec3& r = s.rho[i];
        if (!finite(r) || r.x < 0 || r.y < 0 || r.z < 0) {
            why << "patch " << i << " has an invalid reflectance";
            return why.str();
        }
        if (r.x >= 1 || r.y >= 1 || r.z >= 1) {
            why << "patch " << i << " reflects all light (reflectance >= 1): the radiosity "
                << "iteration would not converge; lower the diffuse value or limit bounces";
            return why.str();
        }
        const glm::dvec3& e = s.emission[i];
        if (!finite(e) || e.x < 0 || e.y < 0 || e.z < 0) {
            why << "patch " << i << " has an invalid emission";
            return why.str();
        }
        if (!std::isfinite(s.area[i]) || s.area[i] < 0) {
            why << "patch " << i << " has an invalid area";
            return why.str();
        }
        double sum = 0;
        for (size_t j = 0; j < n; ++j) {
            const double f = s.F(i, j);
            if (!std::isfinite(f) || f < 0 || f > 1) {
                why << "form factor F(" << i << ", " << j << ") is outside [0, 1]";
                return why.str();
            }
            sum += f;
        }
        // Monte Carlo rows may exceed 1 by chance: allow 4 standard errors of the estimate.
        const double sigma = i < s.F.row_sigma.size() ? s.F.row_sigma[i] : 0.0;
        if (sum > 1 + 1e-3 + 4 * sigma) {
            why << "form factors of patch " << i << " sum to " << sum << " (> 1)";
            return why.str();
        }
    }
    return {};
}

void require_stable(const RadiositySystem& s) {
    if (auto why = stability_problem(s); !why.empty()) throw LumenError(SourceLoc{}, why);
}

double residual_of(const RadiositySystem& s, const std::vector<glm::dvec3>& B) {
    double worst = 0;
    for (size_t i = 0; i < s.size(); ++i) {
        glm::dvec3 gathered(0);
        for (size_t j = 0; j < s.size(); ++j) gathered += s.F(i, j) * B[j];
        const glm::dvec3 r = s.emission[i] + s.rho[i] * gathered - B[i];
        const double m = std::max({std::abs(r.x), std::abs(r.y), std::abs(r.z)});
        if (!std::isfinite(m)) return INFINITY;
        worst = std::max(worst, m);
    }
    return worst;
}

SolveReport solve(Solver& solver, const RadiositySystem& s, const SolveOptions& options) {
    SolveReport report;
    if (auto why = stability_problem(s); !why.empty() && !options.allow_unstable) {
        report.status = SolveStatus::Unstable;
        report.message = why;
        return report;
    }
    solver.init(s);
    report.residual = solver.residual();
    while (report.residual > options.tolerance) {
        if (report.iterations >= options.max_iterations) {
            report.status = SolveStatus::IterationCap;
            std::ostringstream m;
            m << solver.name() << " stopped after " << report.iterations
              << " iterations with residual " << report.residual;
            report.message = m.str();
            return report;
        }
        const bool more = solver.step();
        ++report.iterations;
        report.residual = solver.residual();
        // Stop a diverging (allow_unstable) run long before overflow could make NaN.
        if (!std::isfinite(report.residual) || report.residual > 1e100) {
            report.status = SolveStatus::Unstable;
            report.message = solver.name() + " diverged (non-finite radiosity)";
            return report;
        }
        if (!more) break;
    }
    if (report.residual > options.tolerance) {
        report.status = SolveStatus::IterationCap;
        report.message = solver.name() + " ran out of work above the tolerance";
    }
    return report;
}

}  // namespace lumen::render::radiosity
