// POV-Ray 3.7's Penrose tilings, tiling 26 (kites and darts, P2) and 27 (rhombs, P3), rebuilt
// from povray 3.7's 16-bit renders (orthographic views of the plane, color_map [0 rgb 0]
// [1 rgb 1]); tiling 25 (pentagons, P1) is built on 26's, in the second half of the file.
//
// What the renders show for 26 and 27: tiles with edges of length 1 (a kite's long edge, a
// rhomb's side), laid out with the dihedral five-fold symmetry of the tiling about the origin,
// which is the common corner of five kites (26) or five thick rhombs (27), and which stays a
// legal Penrose tiling out to x, z = 1000 and beyond. Such a tiling is reproduced exactly by the
// deflation of Robinson triangles (each tile cut in two along its mirror line) from a "sun" of
// ten triangles about the origin, scaled up by φ^n and deflated n times. The result is the same
// for every n in one class mod 4 (the sun turns into itself after four deflations, not fewer):
// n = 0 mod 4 for 26 and n = 1 mod 4 for 27 match POV, the other classes do not. So a point is
// located by taking the least such n whose sun covers it and descending from the triangle holding
// it to the child holding it, n times: O(log |p|) work, no table.
//
// The value is the tile kind plus a bevel, over the number of kinds (2): kites and thick rhombs
// are kind 0, darts and thin rhombs kind 1. The bevel is linear in d, the distance to the nearest
// edge of the tile (not the cut between its two triangles: the flats are the tile's shape shrunk,
// the outer triangle edges are the tile's): clamp(1 - K·d, 0, 1) (see flat_lift for the floor),
// K = 4.46 for 26 and 3.43009 for 27 (fitted to the renders within a 16-bit step over thousands
// of pixels; 1/K is a little under the thin rhomb's inradius, so thin rhombs keep a tiny flat).
#include "render/patterns/penrose.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace lumen::render {
namespace {

constexpr double kPhi = 1.6180339887498948482;
constexpr double kPi = 3.14159265358979323846;

struct V2 {
    double x, z;
};
V2 operator+(V2 a, V2 b) { return {a.x + b.x, a.z + b.z}; }
V2 operator-(V2 a, V2 b) { return {a.x - b.x, a.z - b.z}; }
V2 operator*(V2 a, double s) { return {a.x * s, a.z * s}; }
double cross(V2 a, V2 b) { return a.x * b.z - a.z * b.x; }
double length(V2 a) { return std::hypot(a.x, a.z); }

// The point a fraction 1/φ of the way from a to b.
V2 golden(V2 a, V2 b) { return a + (b - a) * (1 / kPhi); }

// Distance from p to the line through a and b.
double line_distance(V2 a, V2 b, V2 p) {
    const double l = length(b - a);
    return l > 0 ? std::fabs(cross(b - a, p - a)) / l : length(p - a);
}

// How far p lies inside triangle abc (either winding): the least signed distance to its edges,
// negative outside. Choosing the child with the largest value keeps the descent going where
// rounding puts a point a hair outside every child.
double inside_depth(V2 a, V2 b, V2 c, V2 p) {
    const double s = cross(b - a, c - a) < 0 ? -1 : 1;
    const V2 v[3] = {a, b, c};
    double depth = 1e300;
    for (int i = 0; i < 3; ++i) {
        const V2 e = v[(i + 1) % 3] - v[i];
        const double l = length(e);
        if (l > 0) depth = std::min(depth, s * cross(e, p - v[i]) / l);
    }
    return depth;
}

// A Robinson triangle: kind 0 the acute one (36°, 72°, 72°), kind 1 the obtuse one (108°, 36°,
// 36°).
struct Tri {
    int kind;
    V2 a, b, c;
};

// r at m · 36° from +x (the suns' directions are all multiples of 36°).
V2 polar36(double r, int m) {
    static const auto units = [] {
        std::array<V2, 10> u{};
        for (int k = 0; k < 10; ++k) u[k] = {std::cos(k * kPi / 5), std::sin(k * kPi / 5)};
        return u;
    }();
    const V2 u = units[((m % 10) + 10) % 10];
    return {r * u.x, r * u.z};
}

// Points farther out than this are not located (the value is 0): the descent would take over
// 150 levels, and the input has no digits left below the tile size long before.
constexpr double kFarthest = 1e30;

// The floor under the bevel: POV's flats of every kind but the first sit 1e-6 above k/T (a
// colour_map key at k/T falls below them; measured with keys 2e-5 wide), kind 0's flat at 0.
double flat_lift(int kind, int kinds) { return kind > 0 ? 1e-6 * kinds : 0; }

// The least n = first (mod 4) with φ^n · 0.9 > r, and φ^n; the suns below cover the disc of
// radius 0.95 φ^n.
int sun_level(double r, int first, double& scale) {
    int n = first;
    scale = std::pow(kPhi, first);
    const double step = kPhi * kPhi * kPhi * kPhi;
    while (scale * 0.9 <= r) {
        n += 4;
        scale *= step;
    }
    return n;
}

// Of the n triangles, the one p lies deepest inside (the one holding it; near a shared edge,
// the one it is least outside of).
Tri deepest(const std::array<Tri, 3>& kids, int n, V2 p) {
    int best = 0;
    double depth = -1e300;
    for (int i = 0; i < n; ++i) {
        const double d = inside_depth(kids[i].a, kids[i].b, kids[i].c, p);
        if (d > depth) depth = d, best = i;
    }
    return kids[best];
}

// The child of t holding p, by the deflation rule of the tiling (apex first for 27, apex in the
// middle for 26; these are the usual Robinson rules, e.g. as in Jeff Preshing's "Penrose tiling
// explained").
Tri deflate_rhombs(const Tri& t, V2 p) {
    std::array<Tri, 3> kids;
    int n;
    if (t.kind == 0) {
        const V2 q = golden(t.a, t.b);
        kids[0] = {0, t.c, q, t.b};
        kids[1] = {1, q, t.c, t.a};
        n = 2;
    } else {
        const V2 q = golden(t.b, t.a), r = golden(t.b, t.c);
        kids[0] = {1, r, t.c, t.a};
        kids[1] = {1, q, r, t.b};
        kids[2] = {0, r, q, t.a};
        n = 3;
    }
    return deepest(kids, n, p);
}

Tri deflate_kites(const Tri& t, V2 p) {
    std::array<Tri, 3> kids;
    int n;
    if (t.kind == 0) {
        const V2 q = golden(t.a, t.b), r = golden(t.b, t.c);
        kids[0] = {1, r, q, t.b};
        kids[1] = {0, q, t.a, r};
        kids[2] = {0, t.c, t.a, r};
        n = 3;
    } else {
        const V2 q = golden(t.c, t.a);
        kids[0] = {1, t.b, q, t.a};
        kids[1] = {0, q, t.c, t.b};
        n = 2;
    }
    return deepest(kids, n, p);
}

// The sun's triangle holding p: the one whose wedge about the origin contains p's direction.
template <class Make>
Tri sun_triangle(V2 p, Make make) {
    int best = 0;
    double depth = -1e300;
    for (int k = 0; k < 10; ++k) {
        const Tri t = make(k);
        const double d = inside_depth(t.a, t.b, t.c, p);
        if (d > depth) depth = d, best = k;
    }
    return make(best);
}

// Tiling 27: thin and thick rhombs. The sun is five thick rhombs with their 72° corners at the
// origin, their sides along 0°, 72°, ...: ten obtuse triangles with a 36° corner at the origin,
// the long side (the rhomb's long diagonal) along 36° + 72°k and the apex at distance 1·scale.
double rhomb_tiles(V2 p) {
    double s;
    const int n = sun_level(length(p), 1, s);
    Tri t = sun_triangle(p, [s](int k) {
        const int axis = 1 + 2 * (k / 2);  // 36° + 72° (k / 2)
        return Tri{1, polar36(s, axis + (k % 2 ? 1 : -1)), {0, 0}, polar36(s * kPhi, axis)};
    });
    for (int i = 0; i < n; ++i) t = deflate_rhombs(t, p);
    // The rhomb's edges are the triangle's two equal sides, ab and ac; bc is its diagonal.
    const double d = std::min(line_distance(t.a, t.b, p), line_distance(t.a, t.c, p));
    const int kind = t.kind == 1 ? 0 : 1;  // thick rhombs (obtuse halves) first
    return (kind + std::clamp(1 - 3.43009 * d, flat_lift(kind, 2), 1.0)) / 2;
}

// Tiling 26: kites and darts. The sun is five kites with their tips at the origin: ten acute
// triangles with the apex (b, the middle vertex) at the origin and legs of length scale along
// 36°k; the kites' mirror lines lie along 0°, 72°, ...
double kite_tiles(V2 p) {
    double s;
    const int n = sun_level(length(p), 0, s);
    Tri t = sun_triangle(p, [s](int k) {
        V2 u = polar36(s, k), v = polar36(s, k + 1);
        if (k % 2 == 0) std::swap(u, v);
        return Tri{0, u, {0, 0}, v};
    });
    for (int i = 0; i < n; ++i) t = deflate_kites(t, p);
    // The tile's edges are ab and ca; bc is the kite's or dart's mirror line.
    const double d = std::min(line_distance(t.a, t.b, p), line_distance(t.c, t.a, p));
    return (t.kind + std::clamp(1 - 4.46 * d, flat_lift(t.kind, 2), 1.0)) / 2;
}

// Tiling 25: Penrose's pentagons (P1). Six kinds: pentagons of three kinds (0, 1, 2), stars (3),
// boats (4), diamonds (5), edges of length 1, a kind-0 pentagon centred on the origin with a corner
// on -x. The renders show that POV's layout, kinds included, is a fixed decoration of the Robinson
// triangles of the kite-and-dart hierarchy above: the sun of kite_tiles with n = 1 mod 4 (not 26's
// class), scaled by R = 1/(2 sin 36°), the pentagon's circumradius, taken at the level where the
// acute triangles' legs are R·φ^4. Pixels at the same place in different triangles of one type
// (acute or obtuse, either winding) agree over 280000 pairs, out to x, z ~ 1000. The tables hold,
// for each type, the tiles meeting its triangle, in the triangle's affine coordinates (point =
// a + s (b - a) + t (c - a)): fitted to the renders' bevels and snapped to the tiling's module,
// they are numbers (m + n√5)/4.
//
// The bevel is clamp(1 - 3.43008 d, 0, 1), as for 27; d is the distance to the lines of a
// pentagon's or diamond's edges, and for a star or a boat the tile is cut into kites (centre,
// concave corner, point, concave corner): d is the distance to the two outer edges of the kite
// holding the point, and in a boat never more than the distance to its flat side (the boat's
// middle, past the missing points' cut, falls to that side). All fitted within a 16-bit step.
enum Shape { kPentagon, kDiamond, kStar, kBoat };

struct DecorTile {
    int kind;
    Shape shape;
    V2 centre;
    int n;
    V2 v[10];  // pentagon, diamond: corners; star: point, concave corner, ... (10); boat: point,
               // concave, point, flat side's two ends, point, concave (7), the middle point first
};

struct Decoration {
    DecorTile tiles[12];
};

// The tables' numbers, (m + n√5)/4.
constexpr double q(int m, int n) { return (m + n * 2.2360679774997896964) / 4; }

// Indexed by 2 · triangle kind + (1 if c - a turns counter-clockwise from b - a).
const Decoration kDecorations[4] = {
    // acute, b - a turning clockwise to c - a
    {{
        {0, kPentagon, {q(0, 0), q(0, 0)}, 5, {{q(-22, 10), q(14, -6)}, {q(14, -6), q(-14, 6)},
            {q(0, 0), q(8, -4)}, {q(-14, 6), q(0, 0)}, {q(22, -10), q(-8, 4)}}},
        {2, kPentagon, {q(0, 0), q(6, -2)}, 5, {{q(14, -6), q(6, -2)}, {q(-22, 10), q(14, -6)},
            {q(22, -10), q(-8, 4)}, {q(-14, 6), q(20, -8)}, {q(0, 0), q(-2, 2)}}},
        {1, kPentagon, {q(14, -6), q(-2, 2)}, 5, {{q(-8, 4), q(12, -4)}, {q(28, -12), q(-16, 8)},
            {q(14, -6), q(6, -2)}, {q(0, 0), q(-2, 2)}, {q(36, -16), q(-10, 6)}}},
        {3, kStar, {q(0, 0), q(4, 0)}, 10, {{q(14, -6), q(-4, 4)}, {q(-22, 10), q(4, 0)},
            {q(-8, 4), q(12, -4)}, {q(36, -16), q(-10, 6)}, {q(0, 0), q(-2, 2)},
            {q(-36, 16), q(26, -10)}, {q(8, -4), q(4, 0)}, {q(22, -10), q(-18, 10)},
            {q(-14, 6), q(10, -2)}, {q(0, 0), q(18, -6)}}},
        {2, kPentagon, {q(-8, 4), q(0, 0)}, 5, {{q(6, -2), q(0, 0)}, {q(-30, 14), q(8, -4)},
            {q(14, -6), q(-14, 6)}, {q(-22, 10), q(14, -6)}, {q(-8, 4), q(-8, 4)}}},
        {5, kDiamond, {q(3, -1), q(-1, 1)}, 4, {{q(28, -12), q(-16, 8)}, {q(-8, 4), q(-8, 4)},
            {q(-22, 10), q(14, -6)}, {q(14, -6), q(6, -2)}}},
        {1, kPentagon, {q(6, -2), q(-8, 4)}, 5, {{q(-16, 8), q(6, -2)}, {q(20, -8), q(-22, 10)},
            {q(6, -2), q(0, 0)}, {q(-8, 4), q(-8, 4)}, {q(28, -12), q(-16, 8)}}},
        {0, kPentagon, {q(6, -2), q(-2, 2)}, 5, {{q(20, -8), q(-2, 2)}, {q(-16, 8), q(6, -2)},
            {q(28, -12), q(-16, 8)}, {q(-8, 4), q(12, -4)}, {q(6, -2), q(-10, 6)}}},
        {4, kBoat, {q(-2, 2), q(0, 0)}, 7, {{q(6, -2), q(0, 0)}, {q(20, -8), q(-22, 10)},
            {q(-16, 8), q(6, -2)}, {q(-2, 2), q(14, -6)}, {q(34, -14), q(-14, 6)},
            {q(-2, 2), q(-6, 2)}, {q(-38, 18), q(22, -10)}}},
        {2, kPentagon, {q(-2, 2), q(6, -2)}, 5, {{q(-24, 12), q(20, -8)}, {q(12, -4), q(-8, 4)},
            {q(-2, 2), q(14, -6)}, {q(-16, 8), q(6, -2)}, {q(20, -8), q(-2, 2)}}},
        {1, kPentagon, {q(12, -4), q(0, 0)}, 5, {{q(26, -10), q(0, 0)}, {q(-10, 6), q(8, -4)},
            {q(34, -14), q(-14, 6)}, {q(-2, 2), q(14, -6)}, {q(12, -4), q(-8, 4)}}},
        {3, kStar, {q(4, 0), q(0, 0)}, 10, {{q(-4, 4), q(0, 0)}, {q(-18, 10), q(22, -10)},
            {q(18, -6), q(-6, 2)}, {q(4, 0), q(-14, 6)}, {q(-10, 6), q(8, -4)},
            {q(26, -10), q(0, 0)}, {q(12, -4), q(-8, 4)}, {q(-32, 16), q(14, -6)},
            {q(4, 0), q(6, -2)}, {q(40, -16), q(-22, 10)}}},
    }},
    // acute, b - a turning counter-clockwise to c - a
    {{
        {0, kPentagon, {q(0, 0), q(0, 0)}, 5, {{q(14, -6), q(-14, 6)}, {q(-22, 10), q(14, -6)},
            {q(22, -10), q(-8, 4)}, {q(-14, 6), q(0, 0)}, {q(0, 0), q(8, -4)}}},
        {2, kPentagon, {q(0, 0), q(6, -2)}, 5, {{q(14, -6), q(6, -2)}, {q(0, 0), q(-2, 2)},
            {q(-14, 6), q(20, -8)}, {q(22, -10), q(-8, 4)}, {q(-22, 10), q(14, -6)}}},
        {1, kPentagon, {q(14, -6), q(-2, 2)}, 5, {{q(28, -12), q(-16, 8)}, {q(-8, 4), q(12, -4)},
            {q(36, -16), q(-10, 6)}, {q(0, 0), q(-2, 2)}, {q(14, -6), q(6, -2)}}},
        {3, kStar, {q(0, 0), q(4, 0)}, 10, {{q(-8, 4), q(12, -4)}, {q(-22, 10), q(4, 0)},
            {q(14, -6), q(-4, 4)}, {q(0, 0), q(18, -6)}, {q(-14, 6), q(10, -2)},
            {q(22, -10), q(-18, 10)}, {q(8, -4), q(4, 0)}, {q(-36, 16), q(26, -10)},
            {q(0, 0), q(-2, 2)}, {q(36, -16), q(-10, 6)}}},
        {2, kPentagon, {q(-8, 4), q(0, 0)}, 5, {{q(6, -2), q(0, 0)}, {q(-8, 4), q(-8, 4)},
            {q(-22, 10), q(14, -6)}, {q(14, -6), q(-14, 6)}, {q(-30, 14), q(8, -4)}}},
        {5, kDiamond, {q(3, -1), q(-1, 1)}, 4, {{q(28, -12), q(-16, 8)}, {q(14, -6), q(6, -2)},
            {q(-22, 10), q(14, -6)}, {q(-8, 4), q(-8, 4)}}},
        {1, kPentagon, {q(6, -2), q(-8, 4)}, 5, {{q(20, -8), q(-22, 10)}, {q(-16, 8), q(6, -2)},
            {q(28, -12), q(-16, 8)}, {q(-8, 4), q(-8, 4)}, {q(6, -2), q(0, 0)}}},
        {0, kPentagon, {q(6, -2), q(-2, 2)}, 5, {{q(20, -8), q(-2, 2)}, {q(6, -2), q(-10, 6)},
            {q(-8, 4), q(12, -4)}, {q(28, -12), q(-16, 8)}, {q(-16, 8), q(6, -2)}}},
        {4, kBoat, {q(-2, 2), q(0, 0)}, 7, {{q(6, -2), q(0, 0)}, {q(-38, 18), q(22, -10)},
            {q(-2, 2), q(-6, 2)}, {q(34, -14), q(-14, 6)}, {q(-2, 2), q(14, -6)},
            {q(-16, 8), q(6, -2)}, {q(20, -8), q(-22, 10)}}},
        {2, kPentagon, {q(-2, 2), q(6, -2)}, 5, {{q(12, -4), q(-8, 4)}, {q(-24, 12), q(20, -8)},
            {q(20, -8), q(-2, 2)}, {q(-16, 8), q(6, -2)}, {q(-2, 2), q(14, -6)}}},
        {1, kPentagon, {q(12, -4), q(0, 0)}, 5, {{q(26, -10), q(0, 0)}, {q(12, -4), q(-8, 4)},
            {q(-2, 2), q(14, -6)}, {q(34, -14), q(-14, 6)}, {q(-10, 6), q(8, -4)}}},
        {3, kStar, {q(4, 0), q(0, 0)}, 10, {{q(-4, 4), q(0, 0)}, {q(40, -16), q(-22, 10)},
            {q(4, 0), q(6, -2)}, {q(-32, 16), q(14, -6)}, {q(12, -4), q(-8, 4)},
            {q(26, -10), q(0, 0)}, {q(-10, 6), q(8, -4)}, {q(4, 0), q(-14, 6)},
            {q(18, -6), q(-6, 2)}, {q(-18, 10), q(22, -10)}}},
    }},
    // obtuse, clockwise
    {{
        {3, kStar, {q(0, 0), q(0, 0)}, 10, {{q(0, 0), q(8, -4)}, {q(-14, 6), q(0, 0)},
            {q(2, -2), q(-8, 4)}, {q(8, -4), q(14, -6)}, {q(-6, 2), q(6, -2)},
            {q(0, 0), q(-22, 10)}, {q(6, -2), q(0, 0)}, {q(-8, 4), q(22, -10)},
            {q(-2, 2), q(-6, 2)}, {q(14, -6), q(-14, 6)}}},
        {1, kPentagon, {q(0, 0), q(-8, 4)}, 5, {{q(0, 0), q(-22, 10)}, {q(-6, 2), q(6, -2)},
            {q(8, -4), q(-16, 8)}, {q(-8, 4), q(-8, 4)}, {q(6, -2), q(0, 0)}}},
        {4, kBoat, {q(0, 0), q(6, -2)}, 7, {{q(0, 0), q(-2, 2)}, {q(14, -6), q(6, -2)},
            {q(-2, 2), q(14, -6)}, {q(-8, 4), q(-8, 4)}, {q(8, -4), q(-16, 8)},
            {q(2, -2), q(12, -4)}, {q(-14, 6), q(20, -8)}}},
        {1, kPentagon, {q(6, -2), q(6, -2)}, 5, {{q(14, -6), q(6, -2)}, {q(0, 0), q(-2, 2)},
            {q(6, -2), q(20, -8)}, {q(12, -4), q(-8, 4)}, {q(-2, 2), q(14, -6)}}},
        {2, kPentagon, {q(0, 0), q(12, -4)}, 5, {{q(0, 0), q(-2, 2)}, {q(-6, 2), q(26, -10)},
            {q(8, -4), q(4, 0)}, {q(-8, 4), q(12, -4)}, {q(6, -2), q(20, -8)}}},
        {0, kPentagon, {q(0, 0), q(4, 0)}, 5, {{q(8, -4), q(4, 0)}, {q(-6, 2), q(-4, 4)},
            {q(0, 0), q(18, -6)}, {q(6, -2), q(-10, 6)}, {q(-8, 4), q(12, -4)}}},
        {2, kPentagon, {q(-2, 2), q(0, 0)}, 5, {{q(6, -2), q(0, 0)}, {q(-8, 4), q(-8, 4)},
            {q(-2, 2), q(14, -6)}, {q(4, 0), q(-14, 6)}, {q(-10, 6), q(8, -4)}}},
        {5, kDiamond, {q(2, 0), q(2, 0)}, 4, {{q(-8, 4), q(12, -4)}, {q(-2, 2), q(-16, 8)},
            {q(12, -4), q(-8, 4)}, {q(6, -2), q(20, -8)}}},
        {0, kPentagon, {q(4, 0), q(0, 0)}, 5, {{q(4, 0), q(-14, 6)}, {q(-2, 2), q(14, -6)},
            {q(12, -4), q(-8, 4)}, {q(-4, 4), q(0, 0)}, {q(10, -2), q(8, -4)}}},
    }},
    // obtuse, counter-clockwise
    {{
        {3, kStar, {q(0, 0), q(0, 0)}, 10, {{q(0, 0), q(8, -4)}, {q(14, -6), q(-14, 6)},
            {q(-2, 2), q(-6, 2)}, {q(-8, 4), q(22, -10)}, {q(6, -2), q(0, 0)},
            {q(0, 0), q(-22, 10)}, {q(-6, 2), q(6, -2)}, {q(8, -4), q(14, -6)},
            {q(2, -2), q(-8, 4)}, {q(-14, 6), q(0, 0)}}},
        {1, kPentagon, {q(0, 0), q(-8, 4)}, 5, {{q(0, 0), q(-22, 10)}, {q(6, -2), q(0, 0)},
            {q(-8, 4), q(-8, 4)}, {q(8, -4), q(-16, 8)}, {q(-6, 2), q(6, -2)}}},
        {4, kBoat, {q(0, 0), q(6, -2)}, 7, {{q(0, 0), q(-2, 2)}, {q(-14, 6), q(20, -8)},
            {q(2, -2), q(12, -4)}, {q(8, -4), q(-16, 8)}, {q(-8, 4), q(-8, 4)},
            {q(-2, 2), q(14, -6)}, {q(14, -6), q(6, -2)}}},
        {1, kPentagon, {q(6, -2), q(6, -2)}, 5, {{q(-2, 2), q(14, -6)}, {q(12, -4), q(-8, 4)},
            {q(6, -2), q(20, -8)}, {q(0, 0), q(-2, 2)}, {q(14, -6), q(6, -2)}}},
        {2, kPentagon, {q(0, 0), q(12, -4)}, 5, {{q(0, 0), q(-2, 2)}, {q(6, -2), q(20, -8)},
            {q(-8, 4), q(12, -4)}, {q(8, -4), q(4, 0)}, {q(-6, 2), q(26, -10)}}},
        {0, kPentagon, {q(0, 0), q(4, 0)}, 5, {{q(-8, 4), q(12, -4)}, {q(6, -2), q(-10, 6)},
            {q(0, 0), q(18, -6)}, {q(-6, 2), q(-4, 4)}, {q(8, -4), q(4, 0)}}},
        {2, kPentagon, {q(-2, 2), q(0, 0)}, 5, {{q(-10, 6), q(8, -4)}, {q(4, 0), q(-14, 6)},
            {q(-2, 2), q(14, -6)}, {q(-8, 4), q(-8, 4)}, {q(6, -2), q(0, 0)}}},
        {5, kDiamond, {q(2, 0), q(2, 0)}, 4, {{q(12, -4), q(-8, 4)}, {q(-2, 2), q(-16, 8)},
            {q(-8, 4), q(12, -4)}, {q(6, -2), q(20, -8)}}},
        {0, kPentagon, {q(4, 0), q(0, 0)}, 5, {{q(4, 0), q(-14, 6)}, {q(10, -2), q(8, -4)},
            {q(-4, 4), q(0, 0)}, {q(12, -4), q(-8, 4)}, {q(-2, 2), q(14, -6)}}},
    }},
};

// Crossing-number test (the stars and boats are not convex).
bool in_polygon(const V2* v, int n, V2 p) {
    bool in = false;
    for (int i = 0, j = n - 1; i < n; j = i++)
        if ((v[i].z > p.z) != (v[j].z > p.z)) {
            const double x = v[i].x + (p.z - v[i].z) * (v[j].x - v[i].x) / (v[j].z - v[i].z);
            if (x > p.x) in = !in;
        }
    return in;
}

double segment_distance(V2 a, V2 b, V2 p) {
    const V2 ab = b - a;
    const double l2 = ab.x * ab.x + ab.z * ab.z;
    const double along = (p.x - a.x) * ab.x + (p.z - a.z) * ab.z;
    const double f = l2 > 0 ? std::clamp(along / l2, 0.0, 1.0) : 0;
    return length(p - (a + ab * f));
}

bool in_kite(V2 c, V2 q1, V2 t, V2 q2, V2 p) {
    const V2 k[4] = {c, q1, t, q2};
    return in_polygon(k, 4, p);
}

double pentagon_tiles(V2 p) {
    constexpr double kR = 0.85065080835203993218;  // 1 / (2 sin 36°)
    double s;
    const int n = sun_level(length(p) / kR, 5, s);
    s *= kR;
    Tri t = sun_triangle(p, [s](int k) {
        V2 u = polar36(s, k), v = polar36(s, k + 1);
        if (k % 2 == 0) std::swap(u, v);
        return Tri{0, u, {0, 0}, v};
    });
    for (int i = 0; i < n - 4; ++i) t = deflate_kites(t, p);
    const V2 e1 = t.b - t.a, e2 = t.c - t.a;
    const Decoration& deco = kDecorations[2 * t.kind + (cross(e1, e2) > 0 ? 1 : 0)];
    // The tile holding p. The tiles cover their triangle (checked on a 400 × 400 grid of it);
    // should rounding leave p a hair outside all of them, the nearest one is taken.
    const DecorTile* found = nullptr;
    V2 v[10];
    double nearest = 1e300;
    for (const DecorTile& tile : deco.tiles) {
        if (tile.n == 0) break;
        V2 w[10];
        for (int i = 0; i < tile.n; ++i) w[i] = t.a + e1 * tile.v[i].x + e2 * tile.v[i].z;
        double gap = 0;
        if (!in_polygon(w, tile.n, p)) {
            gap = 1e300;
            for (int i = 0; i < tile.n; ++i)
                gap = std::min(gap, segment_distance(w[i], w[(i + 1) % tile.n], p));
        }
        if (gap < nearest) {
            nearest = gap, found = &tile;
            std::copy(w, w + tile.n, v);
        }
        if (gap == 0) break;
    }
    const DecorTile& tile = *found;
    const V2 c = t.a + e1 * tile.centre.x + e2 * tile.centre.z;
    double d = 1e300;
    if (tile.shape == kPentagon || tile.shape == kDiamond) {
        for (int i = 0; i < tile.n; ++i)
            d = std::min(d, line_distance(v[i], v[(i + 1) % tile.n], p));
    } else if (tile.shape == kStar) {
        for (int j = 0; j < 5; ++j) {
            const V2 q1 = v[(2 * j + 9) % 10], tip = v[2 * j], q2 = v[2 * j + 1];
            if (in_kite(c, q1, tip, q2, p)) {
                d = std::min(line_distance(q1, tip, p), line_distance(tip, q2, p));
                break;
            }
        }
        if (d == 1e300)  // on a kite's side: the nearest edge line
            for (int i = 0; i < 10; ++i) d = std::min(d, line_distance(v[i], v[(i + 1) % 10], p));
    } else {
        d = line_distance(v[3], v[4], p);  // the flat side
        const int kites[3][3] = {{6, 0, 1}, {1, 2, 3}, {4, 5, 6}};
        for (const auto& k : kites)
            if (in_kite(c, v[k[0]], v[k[1]], v[k[2]], p)) {
                d = std::min({d, line_distance(v[k[0]], v[k[1]], p),
                              line_distance(v[k[1]], v[k[2]], p)});
                break;
            }
    }
    return (tile.kind + std::clamp(1 - 3.43008 * d, flat_lift(tile.kind, 6), 1.0)) / 6;
}

}  // namespace

double penrose_tiles(int type, double x, double z) {
    const V2 p{x, z};
    if (!(length(p) < kFarthest)) return 0;  // also NaN
    switch (type) {
        case 25: return pentagon_tiles(p);
        case 26: return kite_tiles(p);
        case 27: return rhomb_tiles(p);
        default: return 0;
    }
}

}  // namespace lumen::render
