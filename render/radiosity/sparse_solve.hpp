// Converged solves on the sparse vertex rows of a scene (no dense matrix, so no cap on the
// unknowns): B = c + diag(ρ) F B, per colour channel, with c = E + ρ(H + G_env).
// - Gauss-Seidel sweeps over the rows, in place;
// - progressive refinement (Southwell): shoot the unknown with the largest unshot power
//   |ΔB| × area along its column of F (the rows transposed once), until no unknown has
//   unshot radiosity above tolerance × the largest c.
#pragma once
#include <vector>

#include <glm/vec3.hpp>

#include "render/radiosity/scene_solution.hpp"

namespace lumen::render::radiosity {

struct SparseSolve {
    std::vector<glm::dvec3> B;
    long iterations = 0;  // sweeps or shots
    bool converged = false;
};

// Stops when the largest change of a sweep is <= tolerance × the largest B, or at max_sweeps.
SparseSolve sparse_gauss_seidel(const VertexFormFactors& F, const std::vector<glm::dvec3>& rho,
                                const std::vector<glm::dvec3>& c, double tolerance,
                                long max_sweeps);

SparseSolve sparse_progressive(const VertexFormFactors& F, const std::vector<glm::dvec3>& rho,
                               const std::vector<glm::dvec3>& c, const std::vector<double>& area,
                               double tolerance, long max_shots);

}  // namespace lumen::render::radiosity
