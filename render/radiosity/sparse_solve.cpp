#include "render/radiosity/sparse_solve.hpp"

#include <algorithm>
#include <cmath>
#include <queue>

namespace lumen::render::radiosity {

namespace {

double largest(const glm::dvec3& v) { return std::max({v.x, v.y, v.z}); }

}  // namespace

SparseSolve sparse_gauss_seidel(const VertexFormFactors& F, const std::vector<glm::dvec3>& rho,
                                const std::vector<glm::dvec3>& c, double tolerance,
                                long max_sweeps) {
    SparseSolve s;
    s.B = c;
    const size_t n = c.size();
    while (s.iterations < max_sweeps) {
        double change = 0, size = 1e-300;
        for (size_t u = 0; u < n; ++u) {
            glm::dvec3 g(0);
            for (uint32_t k = F.start[u]; k < F.start[u + 1]; ++k)
                g += double(F.weight[k]) * s.B[F.col[k]];
            const glm::dvec3 next = c[u] + rho[u] * g;
            change = std::max(change, largest(glm::abs(next - s.B[u])));
            size = std::max(size, largest(next));
            s.B[u] = next;
        }
        ++s.iterations;
        if (!std::isfinite(change)) break;
        if (change <= tolerance * size) {
            s.converged = true;
            break;
        }
    }
    return s;
}

SparseSolve sparse_progressive(const VertexFormFactors& F, const std::vector<glm::dvec3>& rho,
                               const std::vector<glm::dvec3>& c, const std::vector<double>& area,
                               double tolerance, long max_shots) {
    SparseSolve s;
    const size_t n = c.size();
    // Columns: for each shooter i, the receivers j with F_ji > 0 (the rows transposed).
    std::vector<uint32_t> start(n + 1, 0), row;
    std::vector<float> weight;
    for (uint32_t k : F.col) ++start[k + 1];
    for (size_t i = 0; i < n; ++i) start[i + 1] += start[i];
    row.resize(F.col.size());
    weight.resize(F.col.size());
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    for (uint32_t j = 0; j < n; ++j)
        for (uint32_t k = F.start[j]; k < F.start[j + 1]; ++k) {
            const uint32_t at = fill[F.col[k]]++;
            row[at] = j;
            weight[at] = F.weight[k];
        }

    s.B = c;
    std::vector<glm::dvec3> unshot = c;
    // Unshot radiosity at or below tolerance × the largest of c is left unshot (the same
    // measure as the sweeps' change).
    double top = 1e-300;
    for (const glm::dvec3& x : c) top = std::max(top, largest(x));
    const double stop = tolerance * top;
    // Largest unshot power first; stale entries (the power changed since) are skipped.
    std::priority_queue<std::pair<double, uint32_t>> queue;
    auto power = [&](uint32_t u) { return largest(glm::abs(unshot[u])) * area[u]; };
    auto pending = [&](uint32_t u) { return largest(glm::abs(unshot[u])) > stop; };
    for (uint32_t u = 0; u < n; ++u)
        if (pending(u)) queue.emplace(power(u), u);
    while (!queue.empty() && s.iterations < max_shots) {
        const auto [p, i] = queue.top();
        queue.pop();
        if (p != power(i)) continue;
        const glm::dvec3 shot = unshot[i];
        unshot[i] = glm::dvec3(0);
        ++s.iterations;
        for (uint32_t k = start[i]; k < start[i + 1]; ++k) {
            const uint32_t j = row[k];
            const glm::dvec3 add = rho[j] * double(weight[k]) * shot;
            s.B[j] += add;
            unshot[j] += add;
            if (pending(j)) queue.emplace(power(j), j);
        }
        if (!std::isfinite(largest(s.B[i]))) break;
    }
    s.converged = queue.empty();
    return s;
}

}  // namespace lumen::render::radiosity
