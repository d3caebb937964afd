#include "render/patterns/pavement.hpp"

#include <algorithm>
#include <cmath>

#include "render/patterns/pavement_cells.hpp"
#include "scene/pavement_layouts.hpp"

namespace lumen::render {
namespace {

constexpr bool tables_fill_their_periods() {
    for (const scene::PavementLayout& l : scene::kPavementLayouts)
        if (l.cells.size() != std::size_t(l.width * l.height)) return false;
    return true;
}
static_assert(tables_fill_their_periods(), "a pavement table's rows do not match its period");

// One corner of a square cell, (cx, cz) in {0, 1}²: du and dv are twice the distances from it
// along x and z (0 at the corner, 2 at the far side).
struct Corner {
    int cx, cz;
    bool wall_x, wall_z;  // the sides at x = cx and at z = cz are walls
    bool concave;         // neither is, but the diagonal neighbour is another tile
};

// Square cells (POV-Ray's tetragonal pavement). The walls ramp 1 - d to the side; a concave
// corner adds min (interior 0), a diagonal (1) or a round (2) cap; where two walls meet,
// exterior 1 blunts and 2 rounds the corner. A cell with two walls whose opposite corner is
// concave (a bend) takes its own shape under form 0-2: form 0 keeps the sharp corner (no
// interior or exterior shaping), 1 a diagonal and 2 a circular bend; form 3 is the generic sum.
double square_cells(const scene::PavementLayout& l, const scene::pattern::Pavement& k, double x,
                    double z) {
    const long xv = long(std::floor(x)), zv = long(std::floor(z));
    const double u = x - double(xv), v = z - double(zv);
    const char self = l.at(xv, zv);
    const auto other = [&](int dx, int dz) { return l.at(xv + dx, zv + dz) != self; };
    const bool wall[2][2] = {{other(-1, 0), other(1, 0)}, {other(0, -1), other(0, 1)}};
    Corner corners[4];
    for (int i = 0; i < 4; ++i) {
        const int cx = i & 1, cz = i >> 1;
        const bool wx = wall[0][cx], wz = wall[1][cz];
        corners[i] = {cx, cz, wx, wz, !wx && !wz && other(cx ? 1 : -1, cz ? 1 : -1)};
    }
    const auto du = [&](const Corner& c) { return 2 * std::fabs(u - c.cx); };
    const auto dv = [&](const Corner& c) { return 2 * std::fabs(v - c.cz); };
    double walls = 0;
    if (wall[0][0]) walls = std::max(walls, 1 - 2 * u);
    if (wall[0][1]) walls = std::max(walls, 2 * u - 1);
    if (wall[1][0]) walls = std::max(walls, 1 - 2 * v);
    if (wall[1][1]) walls = std::max(walls, 2 * v - 1);
    const int form = int(k.form), interior = int(k.interior), exterior = int(k.exterior);
    if (form != 3)
        for (const Corner& c : corners) {
            // The opposite corner holds both walls of a bend.
            const Corner& o = corners[3 - (c.cx + 2 * c.cz)];
            if (!c.concave || !o.wall_x || !o.wall_z) continue;
            const double a = du(c), b = dv(c);
            if (form == 0) return std::max(walls, std::min(1 - a, 1 - b));
            if (form == 1) return std::min(std::fabs(a + b - 1), 1.0);
            return std::min(std::fabs(std::hypot(a, b) - 1), 1.0);
        }
    double value = walls;
    for (const Corner& c : corners) {
        const double a = du(c), b = dv(c);
        if (c.concave) {
            const double cap = interior == 0   ? std::min(1 - a, 1 - b)
                               : interior == 1 ? 1 - (a + b)
                                               : 1 - std::hypot(a, b);
            value = std::max(value, cap);
        }
        if (!c.wall_x || !c.wall_z) continue;
        if (exterior == 1) value = std::max(value, std::min(2 - (a + b), 1.0));
        if (exterior == 2 && a <= 1 && b <= 1)
            value = std::max(value, std::min(std::hypot(1 - a, 1 - b), 1.0));
    }
    return value;
}

}  // namespace

double evaluate(const scene::pattern::Pavement& k, const glm::dvec3& p) {
    const scene::PavementLayout* l =
        scene::pavement_layout(int(k.sides), int(k.tiles), int(k.number));
    if (!l) return 0;  // the interp reports an unmodelled layout unsupported
    if (l->sides == 3) return triangle_cells(*l, k, p.x, p.z);
    if (l->sides == 6) return hexagon_cells(*l, k, p.x, p.z);
    return square_cells(*l, k, p.x, p.z);
}

}  // namespace lumen::render
