#include <algorithm>
#include <cmath>

#include "render/patterns/pavement_cells.hpp"

// Hexagonal cells as POV-Ray 3.7 draws them, read off its renders and pattern values:
// - cells are flat-topped hexagons of side 1, the cell of column c, row r centred at
//   (1 + 1.5c, sqrt3 (r + (c mod 2) / 2)) (scene/pavement_layouts_hexagons.inc);
// - a wall (an edge to another tile) ramps 1 - 2 sqrt3 d at distance d from it, so 0 from a
//   third of the apothem (sqrt3 / 6) on: POV gives 2 sqrt3 n - 2, n the distance from the
//   centre along the edge's normal;
// - the rest depends on the cell's vertex nearest the point (the cell's twelfth between the
//   centre, that vertex and a neighbouring edge's midpoint). Where both of the cell's edges at
//   that vertex are walls (a convex corner), form 1 adds 4 t - 2, t the distance from the centre
//   along the vertex's direction (the corner cut at the edges' midpoints), and form 2
//   2 sqrt3 r - 2, r the distance from the centre (round, touching the edges' midpoints). Where
//   just one is (the tile bends round the vertex, concave), interior 1 adds 1 - 3 h, h the
//   hexagonal distance from the vertex (the largest projection on the six vertex directions),
//   and interior 2 1 - 3 r, r the distance from the vertex.
// - exterior changes nothing for hexagons, and form is taken modulo 3 (form 3 is form 0).
// Every layout, exterior, interior and form matched POV's pattern values to 2e-6 at thousands
// of random points.

namespace lumen::render {
namespace {

constexpr double kSqrt3 = 1.7320508075688772;

// The six edges' outward normals (30 + 60k degrees; edge k faces neighbour k) and the six
// vertices' directions (60j degrees: vertex j joins edges j - 1 and j, at distance 1).
constexpr double kNormal[6][2] = {{kSqrt3 / 2, 0.5}, {0, 1},  {-kSqrt3 / 2, 0.5},
                                  {-kSqrt3 / 2, -0.5}, {0, -1}, {kSqrt3 / 2, -0.5}};
constexpr double kVertex[6][2] = {{1, 0}, {0.5, kSqrt3 / 2}, {-0.5, kSqrt3 / 2},
                                  {-1, 0}, {-0.5, -kSqrt3 / 2}, {0.5, -kSqrt3 / 2}};

long parity(long c) { return ((c % 2) + 2) % 2; }

// The neighbour across edge k of cell (c, r) in the offset rows.
void neighbour(long c, long r, int k, long& nc, long& nr) {
    const long o = parity(c);
    static constexpr int kDc[6] = {1, 0, -1, -1, 0, 1};
    static constexpr int kDr[6][2] = {{0, 1}, {1, 1}, {0, 1}, {-1, 0}, {-1, -1}, {-1, 0}};
    nc = c + kDc[k];
    nr = r + kDr[k][o];
}

}  // namespace

double hexagon_cells(const scene::PavementLayout& l, const scene::pattern::Pavement& k, double x,
                     double z) {
    // The nearest centre: x lies between columns c0 and c0 + 1, z between two rows of each.
    const long c0 = long(std::floor((x - 1) / 1.5));
    long cell_c = c0, cell_r = 0;
    double best = INFINITY, px = 0, pz = 0;
    for (long c = c0; c <= c0 + 1; ++c) {
        const double half = 0.5 * double(parity(c));
        const long r0 = long(std::floor(z / kSqrt3 - half));
        for (long r = r0; r <= r0 + 1; ++r) {
            const double dx = x - (1 + 1.5 * double(c)), dz = z - kSqrt3 * (double(r) + half);
            const double d2 = dx * dx + dz * dz;
            if (d2 < best) best = d2, cell_c = c, cell_r = r, px = dx, pz = dz;
        }
    }
    const char self = l.at(cell_c, cell_r);
    bool wall[6];
    double value = 0;
    for (int e = 0; e < 6; ++e) {
        long nc, nr;
        neighbour(cell_c, cell_r, e, nc, nr);
        wall[e] = l.at(nc, nr) != self;
        if (wall[e])
            value = std::max(value, 2 * kSqrt3 * (px * kNormal[e][0] + pz * kNormal[e][1]) - 2);
    }
    // The nearest vertex (largest projection on its direction).
    int j = 0;
    double t = -INFINITY;
    for (int v = 0; v < 6; ++v) {
        const double p = px * kVertex[v][0] + pz * kVertex[v][1];
        if (p > t) t = p, j = v;
    }
    const bool before = wall[(j + 5) % 6], after = wall[j];
    const int form = int(k.form) % 3, interior = int(k.interior) % 3;
    if (before && after) {
        if (form == 1) value = std::max(value, 4 * t - 2);
        if (form == 2) value = std::max(value, 2 * kSqrt3 * std::hypot(px, pz) - 2);
    } else if (before != after && interior != 0) {
        const double qx = px - kVertex[j][0], qz = pz - kVertex[j][1];
        double h = 0;  // the vertex lies on the hexagon, so some projection is >= 0
        for (const auto& d : kVertex) h = std::max(h, qx * d[0] + qz * d[1]);
        value = std::max(value, 1 - 3 * (interior == 1 ? h : std::hypot(qx, qz)));
    }
    return std::clamp(value, 0.0, 1.0);
}

}  // namespace lumen::render
