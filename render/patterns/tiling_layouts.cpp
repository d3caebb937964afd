// The layouts of POV-Ray 3.7's tilings, read off its renders: every tile has side 1 (the
// rectangles 2 × 1, the large squares of tiling 15 2 × 2); kinds number the tiles as POV
// colours them. Checked against povray 3.7 to its 16-bit output (tests/patterns/tiling_*.pov).
#include "render/patterns/tiling_layouts.hpp"

#include <cmath>
#include <glm/vec4.hpp>
#include <array>
#include <map>













namespace lumen::render {
namespace {

using V = glm::dvec2;
const double kS3 = std::sqrt(3.0), kH = kS3 / 2, kS2 = std::sqrt(2.0);

TilingTile rect(double kind, double x0, double z0, double x1, double z1, double width) {
    return {kind, {{x0, z0}, {x1, z0}, {x1, z1}, {x0, z1}}, {width}};
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

// Tilings 16 and 17 (3.4.6.4): a hexagon ringed by a square on each edge and a triangle at
// each corner; `square_kinds` and `triangle_kinds` give the kinds going round from the square
// below it and the triangle at its lower left.
TilingLayout hexa_square_triangle(int kinds, double hexagon_kind,
                                  std::array<double, 6> square_kinds,
                                  std::array<double, 6> triangle_kinds) {
    const double w = 1 / (2 * kS3);
    const V c{1 + kH, 0.5 + kH};
    TilingLayout l{{0.5, 0}, 3 + kS3, {1.5 + kH, 0.5 + kH}, kinds, {}};
    l.tiles.push_back({hexagon_kind,
                       {c + V{1, 0}, c + V{0.5, kH}, c + V{-0.5, kH}, c + V{-1, 0},
                        c + V{-0.5, -kH}, c + V{0.5, -kH}},
                       {w}});
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
                 {1, {{c, -0.5}, {c, 0.5}, {0.5, c}, {-0.5, c}, {-c, 0.5}, {-c, -0.5},
                      {-0.5, -c}, {0.5, -c}},
                  {0.5}}}};
    }
    // 8, square_triangle: rows of squares (kind 2) between rows of triangles pointing up
    // (0) and down (1), each row of squares shifted half a side from the last.
    {
        const double w = 1 / (2 * kS3);
        m[8] = {{0, 0}, 1, {0.5, 1 + kH}, 3,
                {rect(2, 0, 0, 1, 1, w),
                 {0, {{0, 1}, {1, 1}, {0.5, 1 + kH}}, {w}},
                 {1, {{0, 1}, {0.5, 1 + kH}, {-0.5, 1 + kH}}, {w}}}};
    }
    // 9, hexa_triangle: hexagons (kind 2) with triangles pointing up (0) and down (1)
    // between them (the trihexagonal tiling).
    {
        const double w = 1 / (2 * kS3);
        m[9] = {{0.5, 0}, 2, {1, kS3}, 3,
                {{2, {{0.5, 0}, {1.5, 0}, {2, kH}, {1.5, kS3}, {0.5, kS3}, {0, kH}}, {w}},
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
            l.tiles.push_back(rect(1, s.x, s.y, s.x + 2, s.y + 2, 0.5));
        m[15] = l;
    }
    // 16, hexa_square_triangle: squares 0, triangles 1, hexagons 2.
    m[16] = hexa_square_triangle(3, 2, {0, 0, 0, 0, 0, 0}, {1, 1, 1, 1, 1, 1});
    // 17, hexa_square_triangle_6: the squares by their three directions, the triangles by
    // their two (POV lifts two of the square kinds by 1e-6).
    m[17] = hexa_square_triangle(6, 5, {0, 2.000001, 1.000001, 0, 2.000001, 1.000001},
                                 {4, 3, 4, 3, 4, 3});
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
