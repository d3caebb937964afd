#include <algorithm>
#include <cmath>

#include "render/patterns/pavement_cells.hpp"

// Triangular cells as POV-Ray 3.7 draws them, read off its 16-bit renders (File_Gamma 1):
// - the cells are equilateral triangles of side 1 with edges along x: rows of height sqrt3 / 2
//   from z = 0, the vertices of row j's lower line at x = k + j / 2
//   (scene/pavement_layouts_triangles.inc numbers the cells);
// - a wall (an edge to another tile) ramps 1 - d / r at distance d from it, r = sqrt3 / 6 the
//   cells' inradius (0 at a lone triangle's centre); a cell takes the largest of its walls';
// - the rest is decided vertex by vertex, each of the cell's three corners by the six cells
//   round it:
//   * both of the cell's edges there are walls (a 60 degree corner of the tile): exterior 1
//     adds t / r, t the distance from the cell's centre towards that vertex (the corner cut a
//     third of the way along the edges), exterior 2 adds c / r, c the distance from the centre,
//     in the third of the cell nearest the vertex (round: a lone triangle's value is c / r);
//   * one is a wall and the neighbour across the other edge turns the tile round with a wall
//     of its own (a 120 degree corner made of two cells): form 1 adds 2 - 4 e, e the distance
//     from the vertex along the inner edge (cut straight across it), form 2 q / r - 2, q the
//     distance from the inner edge's far end (round), each in the third nearest the vertex;
//   * neither is a wall but another tile meets the vertex (the tile is straight or concave
//     there, or only touches it): with a, b the projections of p - vertex on the cell's two
//     edges there, interior 0 adds 1 - 2 (a + b) (at a straight wall or a 120 degree notch
//     the walls' ramps carried on, sharp; the cell facing a 60 degree notch is cut flat),
//     interior 1 adds 1 - 3 max(a, b) and interior 2 adds 1 - 3 |p - vertex| (round).
//   All of these are capped at 1 and taken with the walls' ramps by the largest, and the value
//   is at least 0. Exterior does nothing at 120 degree corners, form nothing at 60 degree ones.
// - POV keeps exterior, interior and form as bytes and takes each modulo 3 (form 3 is form 0,
//   exterior 4 is exterior 1, interior 256 is interior 0). Every layout of 1-6 tiles under each of
//   the 36 exterior / interior / form settings matched POV's 16-bit renders to 4 / 65535 at every
//   pixel.

namespace lumen::render {
namespace {

constexpr double kSqrt3 = 1.7320508075688772;
constexpr double kRow = kSqrt3 / 2;  // a row's height
constexpr double kIn = kSqrt3 / 6;   // a cell's inradius
// Unit vectors at 60q degrees: the six edges leaving a vertex; the cell in sector q of a
// vertex lies between rays q and q + 1.
constexpr double kRay[6][2] = {{1, 0},  {0.5, kRow},   {-0.5, kRow},
                               {-1, 0}, {-0.5, -kRow}, {0.5, -kRow}};

// Vertex k of row j's lower line, at (k + j / 2, j sqrt3 / 2), and the cell's sector in it.
struct Corner {
    long k, j;
    int sector;
};

// The six cells round vertex (k, j), sector by sector (counter-clockwise from +x).
void ring(long k, long j, long (&ci)[6], long (&cj)[6]) {
    const long i[6] = {2 * k, 2 * k - 1, 2 * k - 2, 2 * k - 1, 2 * k, 2 * k + 1};
    const long r[6] = {j, j, j, j - 1, j - 1, j - 1};
    for (int q = 0; q < 6; ++q) ci[q] = i[q], cj[q] = r[q];
}

// An exterior, interior or form setting as POV-Ray uses it: a byte, modulo 3.
int setting(double v) { return (int(v) & 255) % 3; }

}  // namespace

double triangle_cells(const scene::PavementLayout& l, const scene::pattern::Pavement& k, double x,
                      double z) {
    // The row, then the cell along it: upward cell 2c has its base on [c, c + 1] of the row's
    // lower line (shifted by j / 2), the downward cells 2c - 1 and 2c + 1 flank it.
    const double fz = z / kRow;
    const long j = long(std::floor(fz));
    const double t = fz - double(j);
    const double xs = x - 0.5 * double(j);
    const long c = long(std::floor(xs));
    const double f = xs - double(c);
    long i;
    Corner corners[3];
    if (f < t / 2) {
        i = 2 * c - 1;
        corners[0] = {c - 1, j + 1, 5}, corners[1] = {c, j + 1, 3}, corners[2] = {c, j, 1};
    } else if (f > 1 - t / 2) {
        i = 2 * c + 1;
        corners[0] = {c, j + 1, 5}, corners[1] = {c + 1, j + 1, 3}, corners[2] = {c + 1, j, 1};
    } else {
        i = 2 * c;
        corners[0] = {c, j, 0}, corners[1] = {c + 1, j, 2}, corners[2] = {c, j + 1, 4};
    }
    const char self = l.at(i, j);
    double vx[3], vz[3];
    for (int n = 0; n < 3; ++n) {
        vx[n] = double(corners[n].k) + 0.5 * double(corners[n].j);
        vz[n] = double(corners[n].j) * kRow;
    }
    const double cx = (vx[0] + vx[1] + vx[2]) / 3, cz = (vz[0] + vz[1] + vz[2]) / 3;
    const int exterior = setting(k.exterior), interior = setting(k.interior),
              form = setting(k.form);

    double value = 0;
    for (int n = 0; n < 3; ++n) {
        long ri[6], rj[6];
        ring(corners[n].k, corners[n].j, ri, rj);
        bool other[6], any = false;
        for (int q = 0; q < 6; ++q) any |= other[q] = l.at(ri[q], rj[q]) != self;
        const int p = corners[n].sector;
        const double* ea = kRay[p];
        const double* eb = kRay[(p + 1) % 6];
        const double dx = x - vx[n], dz = z - vz[n];
        const double a = dx * ea[0] + dz * ea[1], b = dx * eb[0] + dz * eb[1];
        const bool wall_a = other[(p + 5) % 6], wall_b = other[(p + 1) % 6];
        // The third of the cell nearest this vertex (POV shapes its corners there only).
        const bool nearest = a <= 0.5 && b <= 0.5;
        if (wall_a) value = std::max(value, 1 - std::fabs(dx * ea[1] - dz * ea[0]) / kIn);
        if (wall_b) value = std::max(value, 1 - std::fabs(dx * eb[1] - dz * eb[0]) / kIn);
        if (wall_a && wall_b) {
            const double px = x - cx, pz = z - cz;
            if (exterior == 1) {
                const double towards = (px * (vx[n] - cx) + pz * (vz[n] - cz)) / (2 * kIn);
                value = std::max(value, std::min(towards / kIn, 1.0));
            } else if (exterior == 2 && nearest) {
                value = std::max(value, std::min(std::hypot(px, pz) / kIn, 1.0));
            }
        } else if (wall_a != wall_b) {
            // A 120 degree corner: the neighbour across the inner edge has a wall at its far
            // edge. The inner edge runs along ray p + 1 (wall at ray p) or ray p.
            const bool turns = wall_a ? other[(p + 2) % 6] : other[(p + 4) % 6];
            if (!turns || !nearest || (form != 1 && form != 2)) continue;
            const double* e = wall_a ? eb : ea;
            if (form == 1)
                value = std::max(value, std::min(2 - 4 * (dx * e[0] + dz * e[1]), 1.0));
            else
                value = std::max(value, std::min(std::hypot(dx - e[0], dz - e[1]) / kIn - 2, 1.0));
        } else if (any) {
            const double cap = interior == 1   ? 1 - 3 * std::max(a, b)
                               : interior == 2 ? 1 - 3 * std::hypot(dx, dz)
                                               : 1 - 2 * (a + b);
            value = std::max(value, std::min(cap, 1.0));
        }
    }
    return std::clamp(value, 0.0, 1.0);
}

}  // namespace lumen::render
