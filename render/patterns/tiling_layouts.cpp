// The layouts of POV-Ray 3.7's tilings, worked out from its tiling definitions: every tile
// has side 1 (the rectangles 2 × 1, the large squares of tiling 15 2 × 2); kinds number the
// tiles as POV colours them, with its bevel widths, floors and lifts. Each layout matches
// povray 3.7's 16-bit output pixel for pixel, with smooth maps and with hard keys at every
// k/T (tests/patterns/tiling_*.pov, render/patterns/tiling_layouts_test.cpp).
#include "render/patterns/tiling_layouts.hpp"

#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>
#include <map>

namespace lumen::render {
namespace {

using V = glm::dvec2;
const double kS3 = std::sqrt(3.0), kH = kS3 / 2, kS2 = std::sqrt(2.0);

TilingTile rect(double kind, double x0, double z0, double x1, double z1, double width) {
    return {kind, {{x0, z0}, {x1, z0}, {x1, z1}, {x0, z1}}, {width}};
}

// The tile with POV's floor under its bevel.
TilingTile floored(TilingTile t, double least) {
    t.least = least;
    return t;
}

// Tilings 6 and 18: 2 × 1 rectangles in a 4 × 4 cell, lying (kind 0) or standing (kind 1).
TilingLayout rectangles(const std::vector<glm::dvec4>& lying,
                        const std::vector<glm::dvec4>& standing) {
    TilingLayout l{{0, 0}, 4, {0, 4}, 2, {}};
    for (const auto& r : lying) l.tiles.push_back(rect(0, r.x, r.y, r.z, r.w, 0.5));
    for (const auto& r : standing) l.tiles.push_back(rect(1, r.x, r.y, r.z, r.w, 0.5));
    return l;
}

// Tiling 11's 3 × 3 cell: a unit square (kind 0) ringed by 2 × 1 rectangles, lying (1) and
// standing (2), each turning the same way about it.
std::vector<TilingTile> square_rectangle_cell(V at) {
    return {rect(0, at.x + 1, at.y + 1, at.x + 2, at.y + 2, 0.5),
            rect(1, at.x + 1, at.y + 0, at.x + 3, at.y + 1, 0.5),
            rect(1, at.x + 0, at.y + 2, at.x + 2, at.y + 3, 0.5),
            rect(2, at.x + 0, at.y + 0, at.x + 1, at.y + 2, 0.5),
            rect(2, at.x + 2, at.y + 1, at.x + 3, at.y + 3, 0.5)};
}

// The tile turned by `degrees` about `centre`.
TilingTile turned(TilingTile t, V centre, double degrees) {
    const double a = degrees * M_PI / 180, c = std::cos(a), s = std::sin(a);
    for (V& p : t.corners) {
        const V d = p - centre;
        p = centre + V{c * d.x - s * d.y, s * d.x + c * d.y};
    }
    return t;
}

// A regular polygon of side 1 about `centre` whose first edge faces `first_normal` degrees;
// edge k faces first_normal + k · 360 / sides and gets width(facing angle in degrees).
template <class Width>
TilingTile regular(double kind, V centre, int sides, double first_normal, Width width) {
    const double step = 360.0 / sides, radius = 0.5 / std::sin(M_PI / sides);
    TilingTile t{kind, {}, {}};
    for (int k = 0; k < sides; ++k) {
        const double a = (first_normal + step * (k - 0.5)) * M_PI / 180;
        t.corners.push_back(centre + radius * V{std::cos(a), std::sin(a)});
    }
    for (int k = 0; k < sides; ++k) t.widths.push_back(width(first_normal + step * k));
    return t;
}
TilingTile regular(double kind, V centre, int sides, double first_normal, double width) {
    return regular(kind, centre, sides, first_normal, [&](double) { return width; });
}

// Tilings 16 and 17 (3.4.6.4): a hexagon ringed by a square on each edge and a triangle at
// each corner; `square_kinds` and `triangle_kinds` give the kinds going round from the square
// below it and the triangle at its lower left.
TilingLayout hexa_square_triangle(int kinds, double hexagon_kind, double hexagon_least,
                                  std::array<double, 6> square_kinds,
                                  std::array<double, 6> triangle_kinds) {
    const double w = 1 / (2 * kS3);
    const V c{1 + kH, 0.5 + kH};
    TilingLayout l{{0.5, 0}, 3 + kS3, {1.5 + kH, 0.5 + kH}, kinds, {}};
    l.tiles.push_back(floored(regular(hexagon_kind, c, 6, 90, w), hexagon_least));
    const TilingTile square = rect(0, kH + 0.5, -0.5, kH + 1.5, 0.5, w);
    const TilingTile triangle{0, {{0.5, 0}, {kH + 0.5, 0.5}, {kH + 0.5, -0.5}}, {w}};
    for (int k = 0; k < 6; ++k) {
        l.tiles.push_back(turned(square, c, 60 * k));
        l.tiles.back().kind = square_kinds[k];
        l.tiles.push_back(turned(triangle, c, 60 * k));
        l.tiles.back().kind = triangle_kinds[k];
    }
    return l;
}

// Tilings 19 and 20 (3.3.3.3.6): the triangle grid (a corner at the origin, rows of height
// √3/2) less one hexagon per lattice cell, the cells spanned by (7, 0) and `row`; up-pointing
// triangles are kind 0, down-pointing 1, hexagons 2.
TilingLayout snub_hexagonal(V row) {
    const double w = 1 / (2 * kS3);
    TilingLayout l{{0, 0}, 7, row, 3, {}};
    const V hexagon{1, 2 * kH};
    std::vector<V> hexagons;
    for (int j = -3; j <= 3; ++j)
        for (int i = -2; i <= 2; ++i) hexagons.push_back(hexagon + double(j) * row + V{7.0 * i, 0});
    for (const V& c : hexagons)
        if (c.y >= 0 && c.y < row.y && c.x >= 0 && c.x < 7)
            l.tiles.push_back(floored(regular(2, c, 6, 90, w), 1e-6));
    // The bottom row of triangles across the cell, those not inside a hexagon.
    for (int n = -1; n <= 7; ++n)
        for (int down = 0; down <= 1; ++down) {
            const TilingTile t =
                down ? TilingTile{1, {{n + 0.5, kH}, {n + 1.5, kH}, {n + 1.0, 0}}, {w}}
                     : TilingTile{0, {{n + 0.0, 0}, {n + 1.0, 0}, {n + 0.5, kH}}, {w}};
            const V centroid = (t.corners[0] + t.corners[1] + t.corners[2]) / 3.0;
            if (centroid.x < 0 || centroid.x >= 7) continue;
            bool covered = false;
            for (const V& c : hexagons) covered |= glm::length(centroid - c) < kH;
            if (!covered) l.tiles.push_back(t);
        }
    return l;
}

// Tilings 23 and 24 (4.6.12): a dodecagon with a square on every other edge (the first
// facing +x) and a hexagon on the others; every bevel is half a side wide.
TilingLayout dodeca_hex(int kinds, double dodecagon_kind, double hexagon_kind,
                        std::array<double, 6> square_kinds) {
    const V d{1.5 + kH, 1 + kS3};
    TilingLayout l{{0, 0}, 3 + kS3, {1.5 + kH, 1.5 + 1.5 * kS3}, kinds, {}};
    l.tiles.push_back(regular(dodecagon_kind, d, 12, 0, 0.5));
    for (int k = 0; k < 6; ++k) {
        const double a = 60 * k * M_PI / 180, b = (60 * k + 30) * M_PI / 180;
        l.tiles.push_back(
            regular(square_kinds[k], d + (1.5 + kH) * V{std::cos(a), std::sin(a)}, 4, 60 * k, 0.5));
        l.tiles.push_back(
            regular(hexagon_kind, d + (1 + kS3) * V{std::cos(b), std::sin(b)}, 6, 30, 0.5));
    }
    return l;
}

// Tilings 13 and 14: in a cell of side 2√2, a square of side √2 at the centre and a trapezoid
// on each of its sides reaching the cell's corners; kinds: square, trapezoids at +x, −x,
// −z and +z (those along z listed first: POV gives them the diagonals).
TilingLayout square_internal(int kinds, std::array<double, 5> k) {
    const double c = 2 * kS2, a = c / 4, b = 3 * c / 4, w = 0.5 / kS2;
    return {{0, 0}, c, {0, c}, kinds,
            {rect(k[0], a, a, b, b, w),
             {k[3], {{a, a}, {0, 0}, {c, 0}, {b, a}}, {w}},
             {k[4], {{a, b}, {b, b}, {c, c}, {0, c}}, {w}},
             {k[1], {{b, a}, {c, 0}, {c, c}, {b, b}}, {w}},
             {k[2], {{a, a}, {a, b}, {0, c}, {0, 0}}, {w}}}};
}

std::map<int, TilingLayout> make_layouts() {
    std::map<int, TilingLayout> m;
    // 4, lozenge: 60° rhombi all alike.
    m[4] = {{0, 0}, 1, {0.5, kH}, 1, {{0, {{0, 0}, {1, 0}, {1.5, kH}, {0.5, kH}}, {kS3 / 4}}}};
    // 6, rectangle: 2 × 1 bricks in a basket weave of alternating pairs.
    m[6] = rectangles({{1, 0, 3, 1}, {2, 1, 4, 2}, {-1, 2, 1, 3}, {0, 3, 2, 4}},
                      {{0, 0, 1, 2}, {3, -1, 4, 1}, {1, 1, 2, 3}, {2, 2, 3, 4}});
    // 7, octa_square: octagons (kind 1) about the cell's corners, squares (0) at its centre.
    {
        const double p = kS2 + 1, c = p / 2, r = kS2 / 2;
        m[7] = {{0, 0}, p, {0, p}, 2,
                {{0, {{c - r, c}, {c, c - r}, {c + r, c}, {c, c + r}}, {0.5}},
                 floored({1, {{c, -0.5}, {c, 0.5}, {0.5, c}, {-0.5, c}, {-c, 0.5}, {-c, -0.5},
                          {-0.5, -c}, {0.5, -c}},
                          {0.5}},
                         2e-12)}};
    }
    // 8, square_triangle: rows of squares (kind 2) between rows of triangles pointing up
    // (0) and down (1), each row of squares shifted half a side from the last.
    {
        const double w = 1 / (2 * kS3);
        m[8] = {{0, 0}, 1, {0.5, 1 + kH}, 3,
                {rect(2.0000001, 0, 0, 1, 1, w),
                 {0, {{0, 1}, {1, 1}, {0.5, 1 + kH}}, {w}},
                 {1, {{0, 1}, {0.5, 1 + kH}, {-0.5, 1 + kH}}, {w}}}};
    }
    // 9, hexa_triangle: hexagons (kind 2) with triangles pointing up (0) and down (1)
    // between them (the trihexagonal tiling).
    {
        const double w = 1 / (2 * kS3);
        m[9] = {{0.5, 0}, 2, {1, kS3}, 3,
                {floored({2, {{0.5, 0}, {1.5, 0}, {2, kH}, {1.5, kS3}, {0.5, kS3}, {0, kH}}, {w}},
                         1e-7),
                 {0, {{-0.5, 0}, {0.5, 0}, {0, kH}}, {w}},
                 {1, {{0, kH}, {0.5, kS3}, {-0.5, kS3}}, {w}}}};
    }
    // 11, square_rectangle.
    m[11] = {{0, 0}, 3, {0, 3}, 3, square_rectangle_cell({0, 0})};
    // 12, rectangle_square: tiling 11's cell mirrored about x = 3 and z = 3 (the rectangles
    // turn both ways).
    {
        TilingLayout l{{0, 0}, 6, {0, 6}, 3, {}};
        for (TilingTile t : square_rectangle_cell({3, 3}))
            for (int mirror = 0; mirror < 4; ++mirror) {
                TilingTile c = t;
                for (V& p : c.corners) {
                    if (mirror & 1) p.x = 6 - p.x;
                    if (mirror & 2) p.y = 6 - p.y;
                }
                l.tiles.push_back(c);
            }
        m[12] = l;
    }
    // 15, square_double: unit squares (kind 0) and 2 × 2 squares (1) in a 5 × 5 cell.
    {
        TilingLayout l{{0, 0}, 5, {0, 5}, 2, {}};
        for (V s : {V{0, 0}, V{2, 1}, V{4, 2}, V{1, 3}, V{3, 4}})
            l.tiles.push_back(rect(0, s.x, s.y, s.x + 1, s.y + 1, 0.5));
        for (V s : {V{1, -1}, V{3, 0}, V{0, 1}, V{2, 2}, V{-1, 3}})
            l.tiles.push_back(rect(1.00000002, s.x, s.y, s.x + 2, s.y + 2, 0.5));
        m[15] = l;
    }
    // 16, hexa_square_triangle: squares 0, triangles 1, hexagons 2.
    m[16] = hexa_square_triangle(3, 2, 1e-7, {0, 0, 0, 0, 0, 0}, {1, 1, 1, 1, 1, 1});
    // 17, hexa_square_triangle_6: the squares by their three directions, the triangles by
    // their two (POV lifts two of the square kinds by 1e-6).
    m[17] = hexa_square_triangle(6, 5, 1e-6, {0, 2.000001, 1.000001, 0, 2.000001, 1.000001},
                                 {4, 3, 4, 3, 4, 3});
    // 19, hexa_tri_right, and 20, hexa_tri_left: mirror images.
    m[19] = snub_hexagonal({-2.5, kH});
    m[20] = snub_hexagonal({2.5, kH});
    // 13, square_internal: the square 0, the trapezoids along x 2, along z 1.
    m[13] = square_internal(3, {0, 2, 2, 1, 1});
    // 14, square_internal_5: each trapezoid its own kind, the square lifted.
    m[14] = square_internal(5, {4.000001, 0, 1, 2, 3});
    // 21, square_tri (3.3.4.3.4): in each quarter of the cell a square turned by 30° (kind 4
    // where the quarter is mirrored in neither or both axes, 5 otherwise), with triangles
    // on the quarters' sides, kinds 0-3 by their place.
    {
        const double p = 1 + kS3, c = p / 2, w = 1 / (2 * kS3);
        const auto tri = [&](double kind, V a, V b, V t) { return TilingTile{kind, {a, b, t}, {w}}; };
        m[21] = {{0, 0}, p, {0, p}, 6,
                 {floored({4, {{0, 0.5}, {kH, 0}, {c, kH}, {0.5, c}}, {w}}, 1e-6),
                  floored({5, {{p, 0.5}, {1 + kH, 0}, {c, kH}, {p - 0.5, c}}, {w}}, 1e-6),
                  floored({5, {{0, p - 0.5}, {kH, p}, {c, 1 + kH}, {0.5, c}}, {w}}, 1e-6),
                  floored({4, {{p, p - 0.5}, {1 + kH, p}, {c, 1 + kH}, {p - 0.5, c}}, {w}}, 1e-6),
                  tri(0, {0, -0.5}, {0, 0.5}, {kH, 0}),
                  tri(2, {p, -0.5}, {p, 0.5}, {p - kH, 0}),
                  tri(3, {kH, 0}, {1 + kH, 0}, {c, kH}),
                  tri(1, {kH, p}, {1 + kH, p}, {c, p - kH}),
                  tri(1, {-0.5, c}, {0.5, c}, {0, 0.5}),
                  tri(3, {-0.5, c}, {0.5, c}, {0, p - 0.5}),
                  tri(2, {c, kH}, {c, 1 + kH}, {0.5, c}),
                  tri(0, {c, kH}, {c, 1 + kH}, {p - 0.5, c})}};
    }
    // 22, dodeca_tri (3.12.12): dodecagons (kind 2, lifted) with triangles between them
    // pointing up (0) and down (1). POV bevels a dodecagon's edges along x and z over a third
    // of a side and the others over a triangle's inradius, but the cap above its corners at
    // 45° and 135° (which it reaches from the next row of its cell) over the inradius
    // throughout.
    {
        const double w = 1 / (2 * kS3), cap = 1.5 + kS3;
        const V d{1 + kH, 1 + kH};
        TilingTile lower = regular(2.0000001, d, 12, 0, [&](double a) {
            return std::fmod(a, 90) == 0 ? 1.0 / 3 : w;
        });
        TilingTile upper = regular(2.0000001, d, 12, 0, [&](double a) {
            return std::fmod(a, 90) == 0 && a != 90 ? 1.0 / 3 : w;
        });
        lower.cuts = {{V{1, cap}, V{0, cap}}};
        upper.cuts = {{V{0, cap}, V{1, cap}}};
        m[22] = {{0, 0}, 2 + kS3, {1 + kH, cap}, 3,
                 {lower, upper,
                  {0, {{-0.5, 0.5}, {0.5, 0.5}, {0, 0.5 + kH}}, {w}},
                  {1, {{-0.5, cap}, {0.5, cap}, {0, 1.5 + kH}}, {w}}}};
    }
    // 23, dodeca_hex: hexagons 0, squares 1, dodecagons 2 (lifted).
    m[23] = dodeca_hex(3, 2.000001, 0, {1, 1, 1, 1, 1, 1});
    // 24, dodeca_hex_5: the squares by their three directions.
    m[24] = dodeca_hex(5, 4.000001, 0, {1, 2, 3, 1, 2, 3});
    // 18, rectangle_pair: 2 × 1 rectangles paired into squares, the pairs alternating.
    m[18] = rectangles({{2, 0, 4, 1}, {2, 1, 4, 2}, {0, 2, 2, 3}, {0, 3, 2, 4}},
                       {{0, 0, 1, 2}, {1, 0, 2, 2}, {2, 2, 3, 4}, {3, 2, 4, 4}});
    return m;
}

}  // namespace

const TilingLayout* tiling_layout(int n) {
    static const std::map<int, TilingLayout> layouts = make_layouts();
    const auto it = layouts.find(n);
    return it == layouts.end() ? nullptr : &it->second;
}

}  // namespace lumen::render
