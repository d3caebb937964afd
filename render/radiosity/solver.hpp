// Solvers for the radiosity system B = E + diag(ρ) F B, per colour channel. One interface
// (init / step / residual / radiosity) with four methods: LU on the full matrix (the "big
// matrix" reference), Jacobi (one bounce per sweep), Gauss-Seidel (optionally SOR) and
// progressive refinement (Southwell shooting with an ambient term for display).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "render/radiosity/ff_matrix.hpp"
#include "render/radiosity/patch.hpp"

namespace lumen::render::radiosity {

struct RadiositySystem {
    FormFactorMatrix F;
    std::vector<glm::dvec3> rho;       // per patch reflectance
    std::vector<glm::dvec3> emission;  // per patch E
    std::vector<double> area;          // per patch area (progressive shooting, ambient term)

    size_t size() const { return F.n; }
};

// Collects F and the materials of a patch set into a system.
RadiositySystem make_system(const std::vector<Patch>& patches, FormFactorMatrix F);

// Problems that make the iteration diverge or the data meaningless. Empty when the system is
// safe: every ρ in [0, 1), E finite and >= 0, F finite in [0, 1] with row sums <= 1 + 1e-3
// (plus 4 standard errors for Monte Carlo rows, FormFactorMatrix::row_sigma),
// areas finite and > 0 (zero-area patches are allowed only with zero rows).
std::string stability_problem(const RadiositySystem& s);

// The same as a LumenError (no source location) when there is a problem.
void require_stable(const RadiositySystem& s);

// max over patches and channels of |E + ρ F B − B|.
double residual_of(const RadiositySystem& s, const std::vector<glm::dvec3>& B);

class Solver {
public:
    virtual ~Solver() = default;
    virtual std::string name() const = 0;
    // Takes a copy of the system; for LU this is where the factorisation happens.
    virtual void init(const RadiositySystem& s) = 0;
    // One unit of work (a sweep, or one shot for progressive). Returns false when there is
    // nothing left to do (LU after init, progressive with no unshot energy).
    virtual bool step() = 0;
    // An upper bound of max |E + ρ F B − B| at the current iterate.
    virtual double residual() const = 0;
    virtual std::vector<glm::dvec3> radiosity() const = 0;
    // What to show now: B, plus the ambient estimate for progressive refinement.
    virtual std::vector<glm::dvec3> display() const { return radiosity(); }
};

// The state the matrix solvers share: their copy of the system, the iterate B and its residual.
class StoredSystemSolver : public Solver {
public:
    double residual() const override { return residual_; }
    std::vector<glm::dvec3> radiosity() const override { return B_; }

protected:
    // Copies the system and starts from B = E.
    void start(const RadiositySystem& s) {
        system_ = s;
        B_ = s.emission;
        update_residual();
    }
    void update_residual() { residual_ = residual_of(system_, B_); }

    RadiositySystem system_;
    std::vector<glm::dvec3> B_;

private:
    double residual_ = 0;
};

std::unique_ptr<Solver> make_lu_solver();
std::unique_ptr<Solver> make_jacobi_solver();
std::unique_ptr<Solver> make_gauss_seidel_solver(double omega = 1.0);
std::unique_ptr<Solver> make_progressive_solver();

enum class SolveStatus { Converged, IterationCap, Unstable };

struct SolveOptions {
    double tolerance = 1e-10;   // on residual()
    int max_iterations = 100000;
    // Run even when stability_problem() is non-empty (bounce-limited use with a fixed
    // number of Jacobi sweeps); otherwise such a system returns Unstable without iterating.
    bool allow_unstable = false;
};

struct SolveReport {
    SolveStatus status = SolveStatus::Converged;
    int iterations = 0;
    double residual = 0;
    std::string message;  // why it is not Converged
};

// init + step until residual() <= tolerance, no work is left, or the cap is hit. Never
// produces NaN: a non-finite iterate stops the run as Unstable.
SolveReport solve(Solver& solver, const RadiositySystem& s, const SolveOptions& options = {});

}  // namespace lumen::render::radiosity
