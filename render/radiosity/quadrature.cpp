// Gauss-Legendre nodes by Newton's method on the Legendre recurrence.
#include "render/radiosity/quadrature.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <numbers>

namespace lumen::render::radiosity {

Rule gauss_legendre(int order) {
    const int n = std::clamp(order, 1, 64);
    Rule rule(n);
    for (int i = 0; i < n; ++i) {
        double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
        double dp = 1;
        for (int iter = 0; iter < 100; ++iter) {
            double p0 = 1, p1 = x;
            for (int k = 2; k <= n; ++k) {
                const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = n * (x * p1 - p0) / (x * x - 1);
            const double dx = p1 / dp;
            x -= dx;
            if (std::abs(dx) < 1e-16) break;
        }
        // Map [-1, 1] to [0, 1]: node (1 − x)/2 ascending, weight halves.
        rule[i] = {0.5 * (1 - x), 1.0 / ((1 - x * x) * dp * dp)};
    }
    return rule;
}

const Rule& graded_rule(int order, int grading) {
    static std::mutex lock;
    static std::map<std::pair<int, int>, std::unique_ptr<Rule>> cache;
    const int g = std::clamp(grading, 0, 20);
    std::lock_guard guard(lock);
    auto& slot = cache[{order, g}];
    if (slot) return *slot;
    std::vector<double> breaks{0, 0.5, 1};
    double h = 0.5;
    for (int k = 0; k < g; ++k) {
        h *= 0.25;
        breaks.push_back(h);
        breaks.push_back(1 - h);
    }
    std::sort(breaks.begin(), breaks.end());
    const Rule base = gauss_legendre(order);
    auto rule = std::make_unique<Rule>();
    for (size_t c = 0; c + 1 < breaks.size(); ++c) {
        const double lo = breaks[c], len = breaks[c + 1] - lo;
        for (const auto& [x, w] : base) rule->push_back({lo + len * x, len * w});
    }
    slot = std::move(rule);
    return *slot;
}

}  // namespace lumen::render::radiosity
