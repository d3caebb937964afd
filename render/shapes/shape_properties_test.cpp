// Properties every shape of scene/shape_list.hpp must have, checked with random rays on a
// sample instance under several transforms (identity, similarity, mirror, shear). A listed
// shape without a sample_shape overload here does not compile.
#include <cmath>
#include <optional>
#include <random>
#include <type_traits>

#include <gtest/gtest.h>

#include "render/geometry_test_util.hpp"
#include "render/node.hpp"

namespace lumen::render {
namespace {

using namespace testing;

// How closely a shape's hit is found again (world distance); a specialisation beside a
// sample says why a shape needs more.
template <class T> constexpr double kRefindTolerance = 1e-7;
// False where POV-Ray's depth is an estimate that a ray along the normal need not find again.
template <class T> constexpr bool kNormalProbe = true;

// ---- one sample per listed shape ----------------------------------------------------------

scene::Sphere sample_shape(std::type_identity<scene::Sphere>) { return {{0.2, 0.1, 0}, 0.8}; }
scene::Plane sample_shape(std::type_identity<scene::Plane>) {
    return {glm::normalize(glm::dvec3{0.3, 1, 0.2}), 0.4};
}
scene::Box sample_shape(std::type_identity<scene::Box>) { return {{-1, -0.5, -0.2}, {0.7, 1, 1}}; }
scene::Cylinder sample_shape(std::type_identity<scene::Cylinder>) {
    return {{0, -1, 0}, {0.3, 1, 0.2}, 0.5, false};
}
scene::Cone sample_shape(std::type_identity<scene::Cone>) {
    return {{0, -1, 0}, 0.8, {0, 1, 0.3}, 0.2, false};
}
scene::Torus sample_shape(std::type_identity<scene::Torus>) { return {1, 0.3, false}; }
scene::Disc sample_shape(std::type_identity<scene::Disc>) {
    return {{0, 0, 0}, glm::normalize(glm::dvec3{0.2, 1, 0}), 1, 0.3};
}
scene::Triangle sample_shape(std::type_identity<scene::Triangle>) {
    return {{glm::dvec3{-1, -1, 0}, {1, -0.5, 0.2}, {0, 1, -0.1}}, {}, false};
}
scene::Polygon sample_shape(std::type_identity<scene::Polygon>) {  // a square with a hole
    scene::Polygon p;
    p.points = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {-1, -1, 0},
                {-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0, 0.5, 0}, {-0.5, -0.5, 0}};
    return p;
}
scene::Mesh sample_shape(std::type_identity<scene::Mesh>) {  // a closed octahedron, wound outward
    scene::Mesh m;
    m.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int x : {0, 1})
        for (int y : {2, 3})
            for (int z : {4, 5}) {
                bool outward = ((x == 0) == (y == 2)) == (z == 4);  // parity of the octant's signs
                m.faces.push_back({outward ? std::array{x, y, z} : std::array{x, z, y}});
            }
    m.inside_vector = glm::dvec3{0.3, 0.5, 0.7};
    return m;
}

// Two glyphs side by side: a rounded ring (quadratic edges with implied on-curve midpoints,
// a hole wound the other way) and a triangle raised and pushed back by a text offset.
scene::Text sample_shape(std::type_identity<scene::Text>) {
    scene::Text t;
    t.thickness = 0.5;
    scene::Text::Glyph ring;
    ring.points = {{{0, 0.2}, true},   {{0, 1}, false},     {{0.8, 1}, true},
                   {{1, 1}, false},    {{1, 0}, true},      {{0.5, -0.2}, false},
                   {{0.2, 0}, false},  {{0.3, 0.3}, true},  {{0.7, 0.3}, true},
                   {{0.7, 0.7}, false}, {{0.3, 0.7}, true}};
    ring.contour_ends = {7, 11};
    scene::Text::Glyph triangle;
    triangle.position = {1.3, 0.1, 0.2};
    triangle.points = {{{0, 0}, true}, {{0.5, 1}, true}, {{1, 0}, true}};
    triangle.contour_ends = {3};
    t.glyphs = {ring, triangle};
    return t;
}

// A Catmull-Rom diamond with a smaller one inside it as a hole, swept from -0.5 to 0.7.
scene::Prism sample_shape(std::type_identity<scene::Prism>) {
    scene::Prism p;
    p.spline = scene::SplineKind::Cubic;
    p.height1 = -0.5;
    p.height2 = 0.7;
    for (double r : {1.0, 0.3})
        for (glm::dvec2 q : {glm::dvec2{0, -1}, {1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1, 0}, {0, 1}})
            p.points.push_back(r * q);
    return p;
}
// A closed Catmull-Rom loop clear of the axis, turned: a lumpy ring (degree 6 in w).
scene::Lathe sample_shape(std::type_identity<scene::Lathe>) {
    scene::Lathe l;
    l.spline = scene::SplineKind::Cubic;
    l.points = {{0.2, 0.8}, {0.3, -0.8}, {1, -0.5}, {0.8, 0.6}, {0.2, 0.8}, {0.3, -0.8}, {1, -0.5}};
    return l;
}
scene::Sor sample_shape(std::type_identity<scene::Sor>) {  // a capped vase
    scene::Sor s;
    s.points = {{0, -1.2}, {0.5, -1}, {0.8, 0}, {0.4, 1}, {0.6, 1.3}};
    return s;
}
// A torus (R 1, r 0.4) written as a quartic. Scaled by 1000: POV-Ray's poly counts F < 1e-4
// as inside, so F must grow faster than 1e-4 per 1e-6 step off the surface for the
// normal test's inside/outside probes.
scene::Poly sample_shape(std::type_identity<scene::Poly>) {
    scene::Poly p;
    p.order = 4;
    p.coeffs.assign(scene::Poly::term_count(4), 0);
    auto set = [&](int i, int j, int k, double c) { p.coeffs[scene::Poly::term_index(4, i, j, k)] = 1000 * c; };
    // (x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + z^2), R^2 - r^2 = 0.84
    const double a = 0.84;
    set(4, 0, 0, 1); set(0, 4, 0, 1); set(0, 0, 4, 1);
    set(2, 2, 0, 2); set(2, 0, 2, 2); set(0, 2, 2, 2);
    set(2, 0, 0, 2 * a - 4); set(0, 2, 0, 2 * a); set(0, 0, 2, 2 * a - 4);
    set(0, 0, 0, a * a);
    return p;
}
// A tilted ellipsoid with a linear term (large enough for the rays aimed within 2 of 0).
scene::Quadric sample_shape(std::type_identity<scene::Quadric>) {
    return {{1, 2, 1.5}, {0.3, 0, 0.2}, {0.1, 0, 0}, -2.5};
}
scene::Superellipsoid sample_shape(std::type_identity<scene::Superellipsoid>) { return {0.5, 0.8}; }
scene::Ovus sample_shape(std::type_identity<scene::Ovus>) { return {1, 0.6}; }
// Two spheres joined by a cylinder, a negative sphere biting one, one component scaled.
scene::Blob sample_shape(std::type_identity<scene::Blob>) {
    scene::Blob b;
    b.threshold = 0.5;
    auto sphere = [](glm::dvec3 c, double r, double s) {
        scene::Blob::Component k;
        k.a = k.b = c;
        k.radius = r;
        k.strength = s;
        return k;
    };
    b.components.push_back(sphere({-0.8, 0, 0}, 1.2, 1));
    b.components.push_back(sphere({0.8, 0.1, 0}, 1.0, 1.5));
    b.components.push_back(sphere({0.8, 0.9, 0}, 0.5, -1));
    scene::Blob::Component cyl;
    cyl.cylinder = true;
    cyl.a = {-1, -0.5, 0};
    cyl.b = {1, -0.5, 0.2};
    cyl.radius = 0.6;
    b.components.push_back(cyl);
    scene::Blob::Component squashed = sphere({0, 0.6, 0}, 1, 1);
    squashed.transform = scene::Transform{glm::dmat4(1.0), glm::dmat4(1.0)};
    squashed.transform->m[0][0] = 1.5;
    squashed.transform->inv[0][0] = 1 / 1.5;
    b.components.push_back(squashed);
    return b;
}
// A 5 x 4 grid of uneven heights (flat normals: smooth ones are not perpendicular to the
// triangles, which the normal test assumes).
scene::HeightField sample_shape(std::type_identity<scene::HeightField>) {
    scene::HeightField h;
    h.columns = 5;
    h.rows = 4;
    h.heights = std::make_shared<const std::vector<uint16_t>>(std::vector<uint16_t>{
        9000, 20000, 30000, 12000, 5000, 15000, 40000, 52000, 30000, 10000,
        8000, 36000, 60000, 41000, 20000, 3000, 10000, 25000, 18000, 7000});
    return h;
}
// With c = 0 the quaternion Julia set is the unit 4-ball; the slice w = 0.5 cuts it in the
// ball of radius sqrt(0.75), clear of the bounding sphere (a slice through the origin touches
// it, and POV-Ray misses crossings in the last step before it). Not tilted: POV-Ray's normal
// leaves out w's dependence on the slice. Precision 1000, so no grazing chord is stepped over.
scene::JuliaFractal sample_shape(std::type_identity<scene::JuliaFractal>) {
    scene::JuliaFractal j;
    j.c = {0, 0, 0, 0};
    j.precision = 1000;
    j.slice_distance = 0.5;
    return j;
}
// A cubic_spline sweep: a bend, a swelling and a radius changing sign (a pinch to a point).
scene::SphereSweep sample_shape(std::type_identity<scene::SphereSweep>) {
    scene::SphereSweep s;
    s.spline = scene::SweepSpline::Cubic;
    s.spheres = {{{-1.2, -0.6, 0}, 0.3}, {{-0.8, 0, 0}, 0.35}, {{0, 0.4, 0.3}, 0.5},
                 {{0.6, -0.2, 0}, -0.2}, {{1, 0.5, -0.3}, 0.3}, {{1.4, 0.8, 0}, 0.3}};
    return s;
}
// x² + y² + z² = 0.8 (a sphere) in a box container that does not cut it, compiled by hand. (Where
// the container cuts the solid, POV-Ray reports the cut face only where a ray starts inside
// the container, so ray parity does not hold there: isosurface_test.cpp.)
scene::Isosurface sample_shape(std::type_identity<scene::Isosurface>) {
    using fn::Op;
    auto p = std::make_shared<fn::Program>();
    p->consts = {0.8};
    p->code = {{Op::Arg, 0, 0, 0}, {Op::Arg, 0, 0, 0}, {Op::Mul}, {Op::Arg, 0, 0, 1},
               {Op::Arg, 0, 0, 1}, {Op::Mul},          {Op::Add}, {Op::Arg, 0, 0, 2},
               {Op::Arg, 0, 0, 2}, {Op::Mul},          {Op::Add}, {Op::Const, 0, 0, 0},
               {Op::Sub}};
    scene::Isosurface s;
    s.function = p;
    s.container.lo = {-1, -0.95, -1};
    s.container.hi = {1.1, 1, 0.95};
    s.max_gradient = 4;
    // Every crossing, found to within 1e-8: the generic properties hold to that precision.
    // (At POV-Ray's default accuracy the depth lies up to 1e-3 inside, and with max_trace 1
    // a ray reports only its first crossing: render/shapes/isosurface_test.cpp.)
    s.accuracy = 1e-8;
    s.max_trace = 10;
    return s;
}
template <> constexpr double kRefindTolerance<scene::Isosurface> = 1e-7;
// A saddle patch (u, 0.3 (u² - v²), v) over -0.9..0.9, compiled by hand. POV-Ray keeps at
// most 32 pieces waiting, which stops splitting at about 2^-15 of the rectangle, and takes
// the depth where the ray enters the last axis's slab (z), not the last slab it enters: a
// ray nearly parallel to z gets a depth up to the piece's size over |d.z| short (lumen's
// renders match POV-Ray's pixel for pixel, shadows included: tests/shapes/parametric.pov).
// So a hit is found again only to within 1e-3 (measured: 8.7e-4 at most), and a ray back
// along the normal (near y here, so nearly parallel to z's slabs) may stop far short.
scene::Parametric sample_shape(std::type_identity<scene::Parametric>) {
    using fn::Op;
    auto arg = [](int i) {
        auto p = std::make_shared<fn::Program>();
        p->code = {{Op::Arg, 0, 0, uint32_t(i)}};
        return p;
    };
    auto y = std::make_shared<fn::Program>();
    y->consts = {0.3};
    y->code = {{Op::Arg, 0, 0, 0}, {Op::Arg, 0, 0, 0}, {Op::Mul}, {Op::Arg, 0, 0, 1},
               {Op::Arg, 0, 0, 1}, {Op::Mul},          {Op::Sub}, {Op::Const, 0, 0, 0},
               {Op::Mul}};
    scene::Parametric s;
    s.functions = {arg(0), y, arg(1)};
    s.uv_lo = {-0.9, -0.9};
    s.uv_hi = {0.9, 0.9};
    s.accuracy = 1e-5;
    s.max_gradient = 1;
    return s;
}
template <> constexpr double kRefindTolerance<scene::Parametric> = 1e-3;
template <> constexpr bool kNormalProbe<scene::Parametric> = false;
// julia_fractal's bisection stops at 1e-7 in object space (POV-Ray's): a hit found twice may
// differ by that much, times the placement's scale.
template <> constexpr double kRefindTolerance<scene::JuliaFractal> = 1e-6;

// ---- an instance compiled the way the renderer compiles it --------------------------------

struct WorldHit {
    double t;
    glm::dvec3 point, normal;  // normal not normalised
};

struct Instance {
    std::unique_ptr<scene::Object> object;  // the store points into it
    NodeStore store;
    uint32_t root = 0;
    Aabb region;  // where the random rays aim

    const Node& node() const { return store.nodes[root]; }
    std::optional<WorldHit> hit(const Ray& r, double tmin) const {
        NodeHit h;
        if (!intersect_node(store, root, r, tmin, Aabb::inf, false, h)) return std::nullopt;
        const Node& leaf = store.nodes[h.leaf];
        glm::dvec3 n = leaf.identity ? h.shape.normal
                                     : store.transforms[leaf.xf].normal(h.shape.normal);
        return WorldHit{h.shape.t, r.at(h.shape.t), leaf.flip ? -n : n};
    }
    bool inside(const glm::dvec3& p) const { return inside_node(store, root, p); }
};

// The part of a shape's world box the random rays aim at: within reach of the sample even
// where the box is infinite (planes).
Aabb aim_region(const Aabb& world_box, const scene::Transform& xf) {
    return intersect(world_box, transformed({glm::dvec3(-2), glm::dvec3(2)}, xf));
}

Instance instance(const scene::Shape& shape, const scene::Transform& xf) {
    Instance in;
    in.object = std::make_unique<scene::Object>();
    in.object->shape = shape;
    in.object->transform = xf;
    in.root = compile_object(in.store, *in.object, NodeContext{});
    in.region = aim_region(in.node().surface, xf);
    return in;
}

struct Placement {
    const char* name;
    scene::Transform xf;
};

std::vector<Placement> placements() {
    return {{"identity", {}},
            {"similarity",
             scale({1.7, 1.7, 1.7}).then(rotate(37, {1, 2, 3})).then(translate({3, -2, 5}))},
            {"mirror", scale({-2, 2, 2}).then(rotate(20, {0, 1, 0})).then(translate({1, 1, 1}))},
            {"shear", from_matrix(glm::dmat4(1, 0.3, 0, 0, 0.2, 1.5, 0.1, 0, 0, 0, -0.8, 0, 1, 2, 3,
                                             1))}};
}

// Rays from a sphere around the region towards random points in it.
class RandomRays {
public:
    explicit RandomRays(const Aabb& region, unsigned seed = 7) : box_(region), rng_(seed) {}
    Ray next() {
        glm::dvec3 target = box_.lo + glm::dvec3(u01(), u01(), u01()) * (box_.hi - box_.lo);
        double reach = glm::length(box_.hi - box_.lo) + 1;
        glm::dvec3 origin = box_.centre() + reach * direction();
        return ray(origin, target - origin);
    }
    glm::dvec3 point() { return box_.lo + glm::dvec3(u01(), u01(), u01()) * (box_.hi - box_.lo); }
    glm::dvec3 direction() {
        glm::dvec3 d;
        do d = glm::dvec3(u01(), u01(), u01()) * 2.0 - 1.0;
        while (glm::dot(d, d) > 1 || glm::dot(d, d) < 1e-4);
        return glm::normalize(d);
    }

private:
    double u01() { return std::uniform_real_distribution<double>(0, 1)(rng_); }
    Aabb box_;
    std::mt19937 rng_;
};

constexpr int kRays = 400;

template <class T> class ShapeProperties : public ::testing::Test {
protected:
    scene::Shape sample() const { return sample_shape(std::type_identity<T>{}); }
    bool sample_is_bounded_solid() const {
        const Aabb solid = instance(sample(), {}).node().solid;
        return !solid.empty() && solid.finite();
    }

    // Calls check(instance, ray, hit) for every hit of kRays random rays, per placement.
    template <class Check> void for_each_hit(const Check& check) const {
        for (const Placement& p : placements()) {
            SCOPED_TRACE(p.name);
            Instance in = instance(sample(), p.xf);
            RandomRays rays(in.region);
            int hits = 0;
            for (int i = 0; i < kRays; ++i) {
                Ray r = rays.next();
                if (auto h = in.hit(r, 0)) {
                    ++hits;
                    check(in, r, *h);
                }
            }
            EXPECT_GT(hits, kRays / 10);
        }
    }
};

using Listed = scene::PrimitiveShapes::apply<::testing::Types>;
TYPED_TEST_SUITE(ShapeProperties, Listed);

TYPED_TEST(ShapeProperties, HitsLieOnTheSurfaceInsideTheBounds) {
    this->for_each_hit([](const Instance& in, const Ray& r, const WorldHit& h) {
        EXPECT_TRUE(in.node().surface.contains(h.point)) << "t " << h.t;
        // Starting again just before the hit finds it again, just ahead (beyond the shape's
        // minimum depth: a blob ignores hits nearer than 1e-2 in its own space).
        const double back = std::max(1e-3, 5 * in.node().min_depth);
        auto again = in.hit({h.point - back * r.dir, r.dir}, 0);
        ASSERT_TRUE(again) << "t " << h.t;
        EXPECT_NEAR(again->t, back, kRefindTolerance<TypeParam>);
    });
}

TYPED_TEST(ShapeProperties, AskedFromAHitTheNextHitLiesBeyondIt) {
    // CSG lists a member's hits by asking again from each one: a shape that works in its own
    // units must not round the distance asked from back onto the same hit.
    this->for_each_hit([](const Instance& in, const Ray& r, const WorldHit& h) {
        if (auto next = in.hit(r, h.t)) {
            EXPECT_GT(next->t, h.t);
        }
    });
}

TYPED_TEST(ShapeProperties, NormalsAreUnitAndFaceOutward) {
    this->for_each_hit([](const Instance& in, const Ray&, const WorldHit& h) {
        const double len = glm::length(h.normal);
        ASSERT_TRUE(std::isfinite(len) && len > 0);
        const glm::dvec3 n = h.normal / len;
        EXPECT_NEAR(glm::length(n), 1, 1e-12);
        if (!kNormalProbe<TypeParam>) return;
        // Perpendicular to the surface: from a step out along it, straight back hits it there.
        const double step = std::max(1e-3, 5 * in.node().min_depth);
        auto back = in.hit({h.point + step * n, -n}, 0);
        ASSERT_TRUE(back);
        EXPECT_NEAR(back->t, step, kRefindTolerance<TypeParam>);
        if (in.node().solid.empty()) return;  // no inside: either side is right
        const double near = 1e-6 * (1 + glm::length(h.point));
        EXPECT_FALSE(in.inside(h.point + near * n)) << "normal points inward";
        EXPECT_TRUE(in.inside(h.point - near * n)) << "normal points inward";
    });
}

TYPED_TEST(ShapeProperties, InsideAgreesWithRayParity) {
    if (!this->sample_is_bounded_solid()) GTEST_SKIP() << "no bounded inside";
    for (const Placement& p : placements()) {
        SCOPED_TRACE(p.name);
        Instance in = instance(this->sample(), p.xf);
        RandomRays rays(in.region, 3);
        int tested = 0, inside = 0;
        for (int i = 0; i < kRays; ++i) {
            const Ray r{rays.point(), rays.direction()};
            int crossings = 0;
            double from = 0;
            bool near_surface = false;
            while (crossings < 64) {
                auto h = in.hit(r, from);
                if (!h) break;
                if (crossings == 0 && h->t < 1e-4) near_surface = true;
                ++crossings;
                from = h->t + 1e-7 * (1 + h->t);
            }
            // A crossing nearer than the minimum depth is not reported: leave such points out.
            const double min_depth = in.node().min_depth;
            if (in.inside(r.origin) != in.inside(r.origin + 5 * min_depth * r.dir)) near_surface = true;
            if (near_surface) continue;
            ++tested;
            inside += in.inside(r.origin);
            EXPECT_EQ(in.inside(r.origin), crossings % 2 == 1) << "point " << i;
        }
        EXPECT_GT(tested, kRays / 2);
        EXPECT_GT(inside, 0);
    }
}

TYPED_TEST(ShapeProperties, BakedFormTracesLikeThePerRayTransform) {
    int baked_placements = 0;
    for (const Placement& p : placements()) {
        SCOPED_TRACE(p.name);
        const scene::Shape shape = this->sample();
        ShapeData baked, local;
        if (!bake_transform(shape, p.xf, baked)) continue;
        ++baked_placements;
        ASSERT_TRUE(prepare_shape(shape, true, local));
        RandomRays rays(aim_region(shape_bounds(baked), p.xf));
        int both = 0, differ = 0;
        for (int i = 0; i < kRays; ++i) {
            const Ray r = rays.next();
            ShapeHit hw, hl;
            bool a = shape_intersect(baked, {r.origin, r.dir}, 1e-6, 1e30, hw);
            bool b = shape_intersect(local, {p.xf.inv_point(r.origin), p.xf.inv_vector(r.dir)},
                                     1e-6, 1e30, hl);
            if (a != b) {
                ++differ;  // grazing rays may round either way
                continue;
            }
            if (!a) continue;
            ++both;
            EXPECT_NEAR(hw.t, hl.t, 1e-9 * (1 + hl.t)) << "ray " << i;
            glm::dvec3 nl = glm::normalize(p.xf.normal(hl.normal)), nw = glm::normalize(hw.normal);
            EXPECT_NEAR(glm::dot(nl, nw), 1, 1e-9) << "ray " << i;
        }
        EXPECT_GT(both, kRays / 10);
        EXPECT_LE(differ, 2);
    }
    if (baked_placements == 0) GTEST_SKIP() << "never baked: traced in object space";
}

}  // namespace
}  // namespace lumen::render
