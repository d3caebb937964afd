// A plane tiling given as data: a lattice cell and the convex tiles it repeats, each with its
// kind and the width of its bevel at each edge. POV-Ray 3.7's tiling patterns put a point in
// a tile of kind k among T kinds at (k + bevel) / T, the bevel being 1 on the tile's edges and
// falling linearly with the distance d from each edge: max(1 − d / width) over the edges,
// floored at 0 or a hair above (flat inside where every edge is farther than its width).
#pragma once
#include <glm/vec2.hpp>
#include <array>
#include <utility>
#include <vector>

namespace lumen::render {

struct TilingTile {
    TilingTile() = default;
    TilingTile(double k, std::vector<glm::dvec2> c, std::vector<double> w,
               std::vector<std::array<glm::dvec2, 2>> cut = {})
        : kind(k), corners(std::move(c)), widths(std::move(w)), cuts(std::move(cut)) {}
    double kind = 0;  // POV lifts some kinds by a hair to keep their flats off a map's key
    std::vector<glm::dvec2> corners;  // convex, any winding (sorted about the centroid)
    std::vector<double> widths;       // one per edge (from corner i to i + 1), or one for all
    // Lines that cut the tile without bevelling it (the tile keeps the left of a → b): POV
    // bevels some tiles differently on either side of its folds.
    std::vector<std::array<glm::dvec2, 2>> cuts;
    double least = 0;  // POV's floor under some bevels (their flats clear a map key at k / T)
};

struct TilingLayout {
    glm::dvec2 origin{0, 0};  // the layout's coordinates are the point's plus this
    double period_x = 1;      // the lattice: (period_x, 0) and row
    glm::dvec2 row{0, 1};
    int kinds = 1;
    std::vector<TilingTile> tiles;
};

// A tiling's compiled form: each tile's edges as half-planes.
class TilingEvaluator {
public:
    explicit TilingEvaluator(const TilingLayout& layout);
    // The pattern's value at (x, z) of the x-z plane, in [0, 1].
    double operator()(double x, double z) const;

private:
    struct Edge {
        glm::dvec2 normal;  // unit, pointing into the tile
        double offset;      // normal · corner
        double inv_width;
    };
    struct Tile {
        double kind, least;
        std::vector<Edge> edges;
        std::vector<Edge> cuts;
    };
    glm::dvec2 origin_, row_;
    double period_x_;
    double kinds_;
    std::vector<Tile> tiles_;
};

}  // namespace lumen::render
