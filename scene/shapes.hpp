// The primitive shapes of scene/shape_list.hpp as plain data, in the object's own
// coordinates as written.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "function/program.hpp"
#include "scene/pattern.hpp"
#include "scene/shared_vector.hpp"
#include "scene/texture.hpp"
#include "scene/transform.hpp"

namespace lumen::scene {

// Each struct lists its parameters in `fields(shape, f)` (f(name, value) for each, f may
// mutate), which content hashing walks (scene/content_hash.hpp): a shape without it does not
// compile there.
#define LUMEN_FIELDS(...) \
    template <class Self, class F> static void fields(Self& s, F&& f) { __VA_ARGS__; }

struct Sphere {
    glm::dvec3 center{0};
    double radius = 1;
    LUMEN_FIELDS(f("center", s.center), f("radius", s.radius))
};
struct Plane {  // n̂·p = d, n normalised
    glm::dvec3 normal{0, 1, 0};
    double distance = 0;
    LUMEN_FIELDS(f("normal", s.normal), f("distance", s.distance))
};
struct Box {  // reordered per axis
    glm::dvec3 min{-1}, max{1};
    LUMEN_FIELDS(f("min", s.min), f("max", s.max))
};
struct Cylinder {
    glm::dvec3 base{0}, cap{0, 1, 0};
    double radius = 1;
    bool open = false;
    LUMEN_FIELDS(f("base", s.base), f("cap", s.cap), f("radius", s.radius), f("open", s.open))
};
struct Cone {
    glm::dvec3 base{0}; double base_radius = 1;
    glm::dvec3 cap{0, 1, 0}; double cap_radius = 0;
    bool open = false;
    LUMEN_FIELDS(f("base", s.base), f("base_radius", s.base_radius), f("cap", s.cap),
                 f("cap_radius", s.cap_radius), f("open", s.open))
};
struct Torus {  // XZ plane, around Y
    double major = 1, minor = 0.25;
    bool sturm = false;
    LUMEN_FIELDS(f("major", s.major), f("minor", s.minor), f("sturm", s.sturm))
};
struct Disc {
    glm::dvec3 center{0}, normal{0, 1, 0};
    double radius = 1, hole = 0;
    LUMEN_FIELDS(f("center", s.center), f("normal", s.normal), f("radius", s.radius),
                 f("hole", s.hole))
};
struct Triangle {
    std::array<glm::dvec3, 3> p{};
    std::array<glm::dvec3, 3> n{};  // vertex normals (normalised), used when smooth
    bool smooth = false;
    std::array<glm::dvec2, 3> uv{};  // `uv_vectors`: only a mesh's triangles use them
    LUMEN_FIELDS(f("points", s.p), f("normals", s.n), f("smooth", s.smooth), f("uv", s.uv))
};
struct Polygon {  // as written (sub-polygons closed)
    std::vector<glm::dvec3> points;
    LUMEN_FIELDS(f("points", s.points))
};
// The bulk (vertices, normals, uvs, faces, textures) is shared by copies of the mesh.
struct Mesh {
    SharedVector<glm::dvec3> vertices;
    SharedVector<glm::dvec3> normals;
    SharedVector<glm::dvec2> uvs;
    struct Face {
        std::array<int, 3> v{};       // vertex indices
        std::array<int, 3> n{-1, -1, -1};  // normal indices (-1 = flat)
        std::array<int, 3> tex{-1, -1, -1};  // texture_list indices (-1 = object texture)
        std::array<int, 3> uv{-1, -1, -1};   // uv indices (-1 = uv (0, 0))
        LUMEN_FIELDS(f("v", s.v), f("n", s.n), f("tex", s.tex), f("uv", s.uv))
    };
    SharedVector<Face> faces;
    SharedVector<LayeredTexture> textures;  // texture_list / per-triangle textures
    std::optional<glm::dvec3> inside_vector;
    // A bicubic_patch's texture corners s0..s3 (its `uv_vectors`), empty for other meshes: the
    // face uvs are then the patch parameters (u, v), mapped bilinearly onto the corners.
    std::vector<glm::dvec2> patch_corners;
    LUMEN_FIELDS(f("vertices", s.vertices), f("normals", s.normals), f("uvs", s.uvs),
                 f("faces", s.faces), f("textures", s.textures),
                 f("inside_vector", s.inside_vector), f("patch_corners", s.patch_corners))
};

// text { ttf "font" "string" thickness, offset }: the glyphs of the string as read from the
// TrueType font and laid out, in em units (1 em = the font's unitsPerEm), extruded from z = 0
// to z = thickness. The points are the font's quadratic outline points as stored, with their
// on-curve flags: the renderer walks them as TrueType does (implied midpoints included).
struct Text {
    struct Point {
        glm::dvec2 p{0};
        bool on_curve = true;
        LUMEN_FIELDS(f("p", s.p), f("on_curve", s.on_curve))
    };
    struct Glyph {
        glm::dvec3 position{0};         // where the glyph's origin is placed
        std::vector<Point> points;      // all contours, each in the font's order
        std::vector<int> contour_ends;  // one past the last point of each contour
        LUMEN_FIELDS(f("position", s.position), f("points", s.points),
                     f("contour_ends", s.contour_ends))
    };
    std::string font;    // the font file as found
    std::string string;  // as written (for the dump)
    double thickness = 1;
    glm::dvec3 offset{0};
    std::vector<Glyph> glyphs;  // one per character, including blank ones
    LUMEN_FIELDS(f("font", s.font), f("string", s.string), f("thickness", s.thickness),
                 f("offset", s.offset), f("glyphs", s.glyphs))
};

// The splines of prism and lathe (POV-Ray's keywords linear_spline ... bezier_spline).
enum class SplineKind { Linear, Quadratic, Cubic, Bezier };

// prism { [spline] [sweep] H1, H2, N, <u,v>... [open] [sturm] }: the 2-D points <u,v> are
// object (x = u, z = v), swept along y from height1 to height2 (height1 <= height2).
// A linear prism's sub-polygons are closed as read (POV-Ray appends the start point).
struct Prism {
    SplineKind spline = SplineKind::Linear;
    bool conic = false;  // conic_sweep: the cone from the origin through the curve at y = 1
    double height1 = 0, height2 = 1;
    std::vector<glm::dvec2> points;
    bool open = false, sturm = false;
    bool closed = true;  // false: an unclosed Bezier prism, which POV-Ray keeps but never hits
    LUMEN_FIELDS(f("spline", s.spline), f("conic", s.conic), f("height1", s.height1),
                 f("height2", s.height2), f("points", s.points), f("open", s.open),
                 f("sturm", s.sturm), f("closed", s.closed))
};
// lathe { [spline] N, <r,y>... [sturm] }: the curve of points <radius, height> turned about y.
struct Lathe {
    SplineKind spline = SplineKind::Linear;
    std::vector<glm::dvec2> points;
    bool sturm = false;
    LUMEN_FIELDS(f("spline", s.spline), f("points", s.points), f("sturm", s.sturm))
};
// sor { N, <r,y>... [open] [sturm] }: r^2 a cubic in y through points 1..N-2 (the first and
// last only steer the slopes), capped at both ends unless open.
struct Sor {
    std::vector<glm::dvec2> points;
    bool open = false, sturm = false;
    LUMEN_FIELDS(f("points", s.points), f("open", s.open), f("sturm", s.sturm))
};

// poly { Order, <coefficients> } (Order 2..35), cubic { <20> } (3), quartic { <35> } (4):
// F(x, y, z) = 0 with F < 0 inside. The coefficients are in POV-Ray's term order: the power of
// x from Order down to 0, within it the power of y, then of z, each from the most left down.
struct Poly {
    int order = 2;
    std::vector<double> coeffs;  // (order+1)(order+2)(order+3)/6 of them
    bool sturm = false;
    LUMEN_FIELDS(f("order", s.order), f("coeffs", s.coeffs), f("sturm", s.sturm))

    static size_t term_count(int order) { return size_t(order + 1) * (order + 2) * (order + 3) / 6; }
    // Where x^i y^j z^k (i + j + k <= order) sits in the term order.
    static size_t term_index(int order, int i, int j, int k) {
        size_t index = 0;
        for (int a = order; a > i; --a) index += size_t(order - a + 1) * (order - a + 2) / 2;
        for (int b = order - i; b > j; --b) index += size_t(order - i - b + 1);
        return index + size_t(order - i - j - k);
    }
};
// quadric { <A,B,C>, <D,E,F>, <G,H,I>, J }:
// A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J = 0, inside where <= 0.
struct Quadric {
    glm::dvec3 square{1}, mixed{0}, linear{0};
    double constant = 1;
    LUMEN_FIELDS(f("square", s.square), f("mixed", s.mixed), f("linear", s.linear),
                 f("constant", s.constant))
};
// superellipsoid { <e, n> }: (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1 in [-1, 1]^3.
struct Superellipsoid {
    double e = 1, n = 1;
    LUMEN_FIELDS(f("e", s.e), f("n", s.n))
};
// height_field { FILE | function W, H {..} [water_level w] [smooth] [hierarchy B] }: heights
// 0..65535 on a grid of columns (x) by rows (z), row z = 0 being the image's bottom row. Cell
// (x, z) is two triangles split by the diagonal (x+1, z)-(x, z+1); the grid fills
// [0,1] x [0, h/65536] x [0,1] before the object's transforms.
struct HeightField {
    int columns = 0, rows = 0;  // each >= 2
    std::shared_ptr<const std::vector<uint16_t>> heights;  // rows * columns, row z = 0 first
    uint64_t heights_hash = 0;  // of the values: hashed and dumped instead of the grid
    double water_level = 0;     // nothing below it is drawn; in units of the field's height
    bool smooth = false, hierarchy = true;
    uint16_t at(int x, int z) const { return (*heights)[size_t(z) * size_t(columns) + size_t(x)]; }
    LUMEN_FIELDS(f("columns", s.columns), f("rows", s.rows), f("heights_hash", s.heights_hash),
                 f("water_level", s.water_level), f("smooth", s.smooth),
                 f("hierarchy", s.hierarchy))
};

// blob { threshold T sphere { <C>, R, [strength] S } cylinder { <A>, <B>, R, S } ... }: the
// surface where the components' summed density S (1 - d^2/R^2)^2 (d < R) equals T. A
// component's transform (written inside its block) places it in the blob's space; its
// texture, if any, is blended with the others' by density where the surface is shaded.
struct Blob {
    struct Component {
        bool cylinder = false;
        glm::dvec3 a{0}, b{0};  // the centre (sphere), or the axis ends (cylinder)
        double radius = 1, strength = 1;
        std::optional<Transform> transform;  // component -> blob space
        LayeredTexture texture;              // empty: the blob's texture
        LUMEN_FIELDS(f("cylinder", s.cylinder), f("a", s.a), f("b", s.b),
                     f("radius", s.radius), f("strength", s.strength),
                     f("transform", s.transform), f("texture", s.texture))
    };
    double threshold = 1;
    std::vector<Component> components;
    bool sturm = false, hierarchy = true;
    LUMEN_FIELDS(f("threshold", s.threshold), f("components", s.components),
                 f("sturm", s.sturm), f("hierarchy", s.hierarchy))
};

// ovus { bottom_radius, top_radius }: a sphere of the bottom radius at the origin, one of the
// top radius centred on its top (0, bottom_radius, 0), joined by the lemon (the inner part of
// a spindle torus) tangent to both whose generating circle has twice the larger radius.
struct Ovus {
    double bottom = 1, top = 0.5;
    LUMEN_FIELDS(f("bottom", s.bottom), f("top", s.top))

    // The lemon: its generating circle (radius `radius`, centre `offset` across the y axis
    // from it at height `height`) and the heights where it meets the spheres.
    struct Lemon {
        double radius, height, offset, low, high;
    };
    Lemon lemon() const {
        const double big = 2 * (bottom > top ? bottom : top);
        const double a = big - bottom, b = big - top;
        Lemon l{big, 0, 0, 0, 0};
        l.height = bottom > 0 ? (a * a - b * b + bottom * bottom) / (2 * bottom) : 0;
        const double e2 = a * a - l.height * l.height;
        l.offset = e2 > 0 ? std::sqrt(e2) : 0;
        l.low = a > 0 ? -l.height * bottom / a : 0;
        l.high = b > 0 ? l.height + big * (bottom - l.height) / b : 0;
        return l;
    }
};

// julia_fractal { <c> [quaternion|hypercomplex] [function] [max_iteration N] [precision P]
// [slice <n>, d] }: the points (x, y, z) whose 4-D point (x, y, z, w), w from n . (x,y,z,w) = d
// (n unit), does not escape under z <- f(z) + c. Quaternions take sqr and cube only.
enum class JuliaAlgebra { Quaternion, Hypercomplex };
enum class JuliaFunction {
    Sqr, Cube, Exp, Reciprocal, Sin, Asin, Sinh, Asinh, Cos, Acos, Cosh, Acosh,
    Tan, Atan, Tanh, Atanh, Ln, Pwr
};
struct JuliaFractal {
    std::array<double, 4> c{1, 0, 0, 0};
    JuliaAlgebra algebra = JuliaAlgebra::Quaternion;
    JuliaFunction function = JuliaFunction::Sqr;
    glm::dvec2 exponent{0};  // pwr(a, b): the complex exponent a + b i
    int max_iteration = 20;
    double precision = 20;
    std::array<double, 4> slice{0, 0, 0, 1};  // unit, slice[3] != 0
    double slice_distance = 0;
    bool csg_child = false;  // a child of a CSG block (set there)
    LUMEN_FIELDS(f("c", s.c), f("algebra", s.algebra), f("function", s.function),
                 f("exponent", s.exponent), f("max_iteration", s.max_iteration),
                 f("precision", s.precision), f("slice", s.slice),
                 f("slice_distance", s.slice_distance), f("csg_child", s.csg_child))

    // POV-Ray's bounding sphere about the origin: radius 1 + |c| (plus 1e-7) up to 2 for
    // quaternions, 4 for hypercomplex numbers. Escaping is |z|^2 > exit_value().
    double bound_radius() const {
        if (algebra == JuliaAlgebra::Hypercomplex) return 4;
        const double r = 1 + std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2] + c[3] * c[3]) + 1e-7;
        return r < 2 ? r : 2;
    }
    double exit_value() const {
        const double r = bound_radius();
        return algebra == JuliaAlgebra::Hypercomplex ? 16 : r * r + 1e-7;
    }
};

// contained_by { box { C1, C2 } | sphere { C, R } } of an isosurface or a parametric: where
// the surface is looked for (POV-Ray's default: the box -1 to 1).
struct Container {
    bool sphere = false;       // a sphere, else a box
    glm::dvec3 lo{-1}, hi{1};  // the box, sorted per axis
    glm::dvec3 center{0};      // the sphere
    double radius = 1;
    LUMEN_FIELDS(f("sphere", s.sphere), f("lo", s.lo), f("hi", s.hi), f("center", s.center),
                 f("radius", s.radius))
    bool empty() const {
        return sphere ? !(radius > 0) : !(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z);
    }
    // POV-Ray's bounding box of the shape: the box, or the sphere's cube.
    glm::dvec3 box_min() const { return sphere ? center - glm::dvec3(radius) : lo; }
    glm::dvec3 box_max() const { return sphere ? center + glm::dvec3(radius) : hi; }
};

// isosurface { function { F } [contained_by { ... }] [threshold T] [accuracy A]
// [max_gradient G] [evaluate P0, P1, P2] [open] [max_trace N | all_intersections] }:
// the surface F = T inside the container (render/shapes/isosurface.hpp), F compiled.
struct Isosurface {
    fn::ProgramPtr function;
    Container container;
    double threshold = 0, accuracy = 0.001, max_gradient = 1.1;
    std::optional<glm::dvec3> evaluate;  // P0, P1, P2
    bool open = false;
    int max_trace = 1;                   // 1..10; all_intersections is 10
    std::shared_ptr<const PatternGlobals> globals;  // the scene's noise_generator
    LUMEN_FIELDS(f("function", s.function), f("container", s.container),
                 f("threshold", s.threshold), f("accuracy", s.accuracy),
                 f("max_gradient", s.max_gradient), f("evaluate", s.evaluate), f("open", s.open),
                 f("max_trace", s.max_trace))
};

// parametric { function { FX } function { FY } function { FZ } <u1, v1>, <u2, v2>
// [contained_by { ... }] [accuracy A] [max_gradient G] [precompute D, x, y, z] }: the points
// (FX, FY, FZ)(u, v) over the uv rectangle, u and v in the functions' first two parameters
// (render/shapes/parametric.hpp). A surface without an inside.
struct Parametric {
    std::array<fn::ProgramPtr, 3> functions;
    glm::dvec2 uv_lo{0}, uv_hi{1};  // sorted
    Container container;
    double accuracy = 0.001, max_gradient = 1;
    int precompute_depth = 0;                 // 0: none; else 1..20
    std::array<bool, 3> precompute{};         // per axis x, y, z
    std::shared_ptr<const PatternGlobals> globals;  // the scene's noise_generator
    LUMEN_FIELDS(f("functions", s.functions), f("uv_lo", s.uv_lo), f("uv_hi", s.uv_hi),
                 f("container", s.container), f("accuracy", s.accuracy),
                 f("max_gradient", s.max_gradient), f("precompute_depth", s.precompute_depth),
                 f("precompute", s.precompute))
};

// sphere_sweep { linear_spline | b_spline | cubic_spline N, <c1>, r1, ... [tolerance T] }:
// the space a sphere fills while its centre and radius follow the spline through the listed
// spheres (render/shapes/sphere_sweep.hpp). Only r^2 matters to the surface (POV-Ray draws a
// radius running from 0.3 to -0.5 as one narrowing to 0 and widening again: measured).
enum class SweepSpline { Linear, BSpline, Cubic };
struct SphereSweep {
    SweepSpline spline = SweepSpline::Linear;
    std::vector<Sphere> spheres;  // as written; b_spline and cubic_spline use the first and
                                  // last only to steer the curve
    double tolerance = 1e-6;      // the depth below which hits are ignored
    LUMEN_FIELDS(f("spline", s.spline), f("spheres", s.spheres), f("tolerance", s.tolerance))

    // POV-Ray's box: every listed sphere's centre -/+ its radius, twice the radius for
    // cubic_spline (measured with min_extent/max_extent). Written radii keep their sign, so
    // all-negative radii give an inverted box, and POV-Ray then draws nothing.
    void control_box(glm::dvec3& lo, glm::dvec3& hi) const {
        const double k = spline == SweepSpline::Cubic ? 2 : 1;
        lo = glm::dvec3(1e300);
        hi = glm::dvec3(-1e300);
        for (const Sphere& p : spheres)
            for (int a = 0; a < 3; ++a) {
                lo[a] = std::min(lo[a], p.center[a] - k * p.radius);
                hi[a] = std::max(hi[a], p.center[a] + k * p.radius);
            }
    }
};

#undef LUMEN_FIELDS

}  // namespace lumen::scene
