// Radiosity solver benchmark: a closed box meshed at several sizes (analytic Lambert form
// factors), one face emitting; prints per solver the time, the iteration count and the
// largest error against LU. Also the early-quality gain of the progressive ambient term.
// Usage: radiosity_solvers [rho]   (default 0.75)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include "render/radiosity/ff_matrix.hpp"
#include "render/radiosity/mesher.hpp"
#include "render/radiosity/solver.hpp"

using namespace lumen::render::radiosity;
using Clock = std::chrono::steady_clock;

namespace {

double seconds_since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

double max_error(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
    double e = 0;
    for (size_t i = 0; i < a.size(); ++i)
        for (int c = 0; c < 3; ++c) e = std::max(e, std::abs(a[i][c] - b[i][c]));
    return e;
}

// Area-weighted relative L1 error (channel 0).
double relative_l1(const RadiositySystem& s, const std::vector<glm::dvec3>& a,
                   const std::vector<glm::dvec3>& ref) {
    double num = 0, den = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        num += s.area[i] * std::abs(a[i].x - ref[i].x);
        den += s.area[i] * ref[i].x;
    }
    return den > 0 ? num / den : 0;
}

}  // namespace

int main(int argc, char** argv) {
    const double rho = argc > 1 ? std::atof(argv[1]) : 0.75;
    std::printf("closed 2x1x1 box, one end emitting, rho = %.3f (red %.3f)\n", rho, rho * 0.6);
    std::printf("%6s %10s %-14s %10s %8s %12s\n", "n", "FF s", "solver", "solve s", "iters",
                "max |B-B_LU|");
    for (double edge : {0.5, 0.34, 0.25, 0.2}) {
        lumen::scene::Object box;
        box.shape = lumen::scene::Box{{0, 0, 0}, {2, 1, 1}};
        MeshOptions opt;
        opt.max_edge = edge;
        opt.inward = true;
        auto patches = mesh_object(box, opt, {glm::dvec3(rho, rho * 0.6, rho), glm::dvec3(0), 0});
        for (auto& p : patches)
            if (p.centroid.x < 1e-9) p.emission = glm::dvec3(1);  // the x = 0 end
        auto t0 = Clock::now();
        const auto F = analytic_matrix(patches, {3, 1});
        const double ff_time = seconds_since(t0);
        const auto s = make_system(patches, F);

        std::vector<glm::dvec3> ref;
        std::vector<std::unique_ptr<Solver>> solvers;
        solvers.push_back(make_lu_solver());
        solvers.push_back(make_jacobi_solver());
        solvers.push_back(make_gauss_seidel_solver());
        solvers.push_back(make_gauss_seidel_solver(1.1));
        solvers.push_back(make_progressive_solver());
        for (auto& solver : solvers) {
            t0 = Clock::now();
            const auto report = solve(*solver, s, {1e-10, 10'000'000});
            const double t = seconds_since(t0);
            if (ref.empty()) ref = solver->radiosity();
            std::printf("%6zu %10.3f %-14s %10.4f %8d %12.3g%s\n", s.size(), ff_time,
                        solver->name().c_str(), t, report.iterations,
                        max_error(solver->radiosity(), ref),
                        report.status == SolveStatus::Converged ? "" : "  (not converged)");
        }
        // Early quality: progressive after n shots, with and without the ambient term.
        auto prog = make_progressive_solver();
        prog->init(s);
        for (size_t k = 0; k < s.size(); ++k) prog->step();
        std::printf("%6s after n shots: rel. L1 error %.4f raw, %.4f with ambient\n", "",
                    relative_l1(s, prog->radiosity(), ref), relative_l1(s, prog->display(), ref));
    }
    return 0;
}
