// Walks a tiling layout: the point is brought into the lattice cell, then the tile holding it
// is found among the layout's tiles and their copies in the eight neighbouring cells (tiles may
// reach out of the cell they are listed in).
#include "render/patterns/tiling_layout.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <stdexcept>

namespace lumen::render {

TilingEvaluator::TilingEvaluator(const TilingLayout& layout)
    : origin_(layout.origin), row_(layout.row), period_x_(layout.period_x),
      kinds_(layout.kinds) {
    for (const TilingTile& t : layout.tiles) {
        // Edge i joins corners i and i + 1; clockwise tiles are turned counter-clockwise.
        std::vector<glm::dvec2> c = t.corners;
        std::vector<double> widths = t.widths;
        const std::size_t n = c.size();
        if (widths.size() != 1 && widths.size() != n)
            throw std::logic_error("tiling layout: one width, or one per edge");
        double area = 0;
        for (std::size_t i = 0; i < n; ++i)
            area += c[i].x * c[(i + 1) % n].y - c[(i + 1) % n].x * c[i].y;
        if (area < 0) {
            std::reverse(c.begin(), c.end());
            if (widths.size() > 1) {
                std::vector<double> w(n);
                for (std::size_t k = 0; k < n; ++k) w[k] = widths[(2 * n - 2 - k) % n];
                widths = w;
            }
        }
        // The line a → b with the tile on its left.
        const auto line = [](glm::dvec2 a, glm::dvec2 b, double width) {
            const glm::dvec2 along = glm::normalize(b - a);
            const glm::dvec2 inward{-along.y, along.x};
            return Edge{inward, glm::dot(inward, a), 1 / width};
        };
        Tile tile{t.kind, t.least, {}, {}};
        for (std::size_t i = 0; i < n; ++i)
            tile.edges.push_back(line(c[i], c[(i + 1) % n], widths[widths.size() == 1 ? 0 : i]));
        for (const auto& cut : t.cuts) tile.cuts.push_back(line(cut[0], cut[1], 1));
        tiles_.push_back(std::move(tile));
    }
}

double TilingEvaluator::operator()(double x, double z) const {
    glm::dvec2 p = glm::dvec2(x, z) + origin_;
    p -= std::floor(p.y / row_.y) * row_;
    p.x -= std::floor(p.x / period_x_) * period_x_;
    // The tile whose nearest edge is farthest (the one holding the point); on an edge, within
    // rounding, the tile listed first (the layouts list tiles in POV's order for its ties).
    double best = -1e300, bevel = 0, kind = 0, least = 0;
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) {
            const glm::dvec2 q = p - double(j) * row_ - glm::dvec2(i * period_x_, 0);
            for (const Tile& t : tiles_) {
                double inside = 1e300, rise = -1e300;
                for (const Edge& e : t.edges) {
                    const double d = glm::dot(e.normal, q) - e.offset;
                    inside = std::min(inside, d);
                    rise = std::max(rise, 1 - d * e.inv_width);
                }
                for (const Edge& e : t.cuts)
                    inside = std::min(inside, glm::dot(e.normal, q) - e.offset);
                if (inside > best + 1e-12) best = inside, bevel = rise, kind = t.kind, least = t.least;
            }
        }
    return std::clamp((kind + std::clamp(bevel, least, 1.0)) / kinds_, 0.0, 1.0);
}

}  // namespace lumen::render
