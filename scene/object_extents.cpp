// POV-Ray's parse-time bounding boxes, measured with min_extent/max_extent on every shape kind
// lumen models. Infinite shapes (planes) get POV's ±1e10; CSG intersections clip with the
// children's boxes and with axis-aligned planes, differences with their first child.
#include "scene/object_extents.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

#include "base/diagnostics.hpp"

namespace lumen::scene {
namespace {

constexpr double kHuge = 1e10;  // POV-Ray's BOUND_HUGE / 2: an unbounded object's box

Extents huge() { return {glm::dvec3(-kHuge), glm::dvec3(kHuge)}; }

Extents empty_box() { return {glm::dvec3(kHuge), glm::dvec3(-kHuge)}; }

void expand(Extents& e, const glm::dvec3& p) {
    e.min = glm::min(e.min, p);
    e.max = glm::max(e.max, p);
}

double volume(const Extents& e) {
    const glm::dvec3 d = glm::max(e.max - e.min, glm::dvec3(0));
    return d.x * d.y * d.z;
}

Extents intersected(const Extents& a, const Extents& b) {
    return {glm::max(a.min, b.min), glm::min(a.max, b.max)};
}

// The axis-aligned box of the 8 corners of `local` mapped by `to_world`.
template <class Map> Extents corners(const Extents& local, Map&& to_world) {
    Extents out = empty_box();
    for (int i = 0; i < 8; ++i)
        expand(out, to_world(glm::dvec3(i & 1 ? local.max.x : local.min.x,
                                        i & 2 ? local.max.y : local.min.y,
                                        i & 4 ? local.max.z : local.min.z)));
    return out;
}

Extents corners(const Extents& local, const scene::Transform& xf) {
    if (xf.is_identity()) return local;
    return corners(local, [&](const glm::dvec3& p) { return xf.point(p); });
}

// POV-Ray's two frames of an axial shape, each taking z onto the unit `axis` (told apart by
// the boxes of tilted shapes): cylinders and cones reflect through the plane between z and
// the axis; discs turn about z × axis.
enum class AxialFrame { Reflect, Turn };

glm::dvec3 frame_of(AxialFrame frame, const glm::dvec3& a, const glm::dvec3& v) {
    if (frame == AxialFrame::Reflect) {
        const glm::dvec3 h = glm::dvec3(0, 0, 1) - a;
        const double len = glm::length(h);
        if (len < 1e-12) return v;
        const glm::dvec3 n = h / len;
        return v - 2 * glm::dot(n, v) * n;
    }
    const glm::dvec3 k(-a.y, a.x, 0);
    const double s = glm::length(k);
    if (s < 1e-12) return a.z < 0 ? glm::dvec3(v.x, -v.y, -v.z) : v;
    const glm::dvec3 kn = k / s;
    const double c = a.z;
    return v * c + glm::cross(kn, v) * s + kn * glm::dot(kn, v) * (1 - c);
}

// The corners of `local` (x, y across the axis, z along it from `base`) in `frame`.
Extents axial_box(AxialFrame frame, const glm::dvec3& base, const glm::dvec3& axis,
                  const Extents& local) {
    const double length = glm::length(axis);
    if (!(length > 0)) return {base, base};
    const glm::dvec3 a = axis / length;
    return corners(local, [&](const glm::dvec3& p) { return base + frame_of(frame, a, p); });
}

Extents round_box(double r, double z0, double z1) {
    return {glm::dvec3(-r, -r, z0), glm::dvec3(r, r, z1)};
}

// Whether the linear part of `xf` is a rotation times a uniform scale (a sphere stays one).
bool similarity(const scene::Transform& xf, double& scale) {
    const glm::dvec3 c0(xf.m[0]), c1(xf.m[1]), c2(xf.m[2]);
    const double l0 = glm::length(c0), l1 = glm::length(c1), l2 = glm::length(c2);
    const double tol = 1e-12 * std::max({l0, l1, l2});
    scale = l0;
    return std::fabs(l0 - l1) <= tol && std::fabs(l0 - l2) <= tol &&
           std::fabs(glm::dot(c0, c1)) <= tol * l0 && std::fabs(glm::dot(c0, c2)) <= tol * l0 &&
           std::fabs(glm::dot(c1, c2)) <= tol * l0;
}

template <class Points> Extents point_range(const Points& points, double pad) {
    Extents e = empty_box();
    for (const glm::dvec3& p : points) expand(e, p);
    e.min -= pad;
    e.max += pad;
    return e;
}

// The shape's own box in object space (its transform applied by the caller), or, for shapes
// whose box POV-Ray computes after the transform, already in world space (`world` set).
struct ShapeBox {
    Extents box;
    bool world = false;
};

struct ShapeBoxes {
    const scene::Transform& xf;
    ShapeBox operator()(const scene::Sphere& s) const {
        double k = 1;
        if (similarity(xf, k)) {  // POV moves the centre and radius: a tight box
            const glm::dvec3 c = xf.point(s.center);
            return {{c - k * s.radius, c + k * s.radius}, true};
        }
        return {{s.center - s.radius, s.center + s.radius}};
    }
    ShapeBox operator()(const scene::Plane&) const { return {huge(), true}; }
    ShapeBox operator()(const scene::Box& b) const { return {{b.min, b.max}}; }
    ShapeBox operator()(const scene::Cylinder& c) const {
        const double len = glm::length(c.cap - c.base);
        return {axial_box(AxialFrame::Reflect, c.base, c.cap - c.base, round_box(c.radius, 0, len))};
    }
    ShapeBox operator()(const scene::Cone& c) const {
        const double len = glm::length(c.cap - c.base);
        const double r = std::max(c.base_radius, c.cap_radius);
        return {axial_box(AxialFrame::Reflect, c.base, c.cap - c.base, round_box(r, 0, len))};
    }
    ShapeBox operator()(const scene::Torus& t) const {
        const double r = t.major + t.minor;
        return {{glm::dvec3(-r, -t.minor, -r), glm::dvec3(r, t.minor, r)}};
    }
    ShapeBox operator()(const scene::Disc& d) const {
        return {axial_box(AxialFrame::Turn, d.center, d.normal, round_box(d.radius, -0.001, 0.001))};
    }
    ShapeBox operator()(const scene::Triangle& t) const {
        std::array<glm::dvec3, 3> w;
        for (int i = 0; i < 3; ++i) w[i] = xf.point(t.p[i]);
        return {point_range(w, 1e-10), true};
    }
    ShapeBox operator()(const scene::Polygon& p) const {
        // POV-Ray boxes a polygon in its plane, 0.001 thick across it (measured in z = 0).
        Extents e = point_range(p.points, 0);
        for (int a = 0; a < 3; ++a)
            if (e.max[a] - e.min[a] == 0) e.min[a] -= 0.001, e.max[a] += 0.001;
        return {e};
    }
    ShapeBox operator()(const scene::Mesh& m) const { return {point_range(m.vertices, 0)}; }
    ShapeBox operator()(const scene::Text& t) const {
        // A union of glyphs, each boxed by its outline points, z from 0 to the thickness.
        Extents e = empty_box();
        for (const scene::Text::Glyph& g : t.glyphs)
            for (const scene::Text::Point& p : g.points) {
                expand(e, g.position + glm::dvec3(p.p, 0));
            }
        if (e.min.x > e.max.x) e = {glm::dvec3(0), glm::dvec3(0)};
        e.min.z = std::min(0.0, t.thickness) - 1e-6;  // POV pads the depth by 1e-6 (measured)
        e.max.z = std::max(0.0, t.thickness) + 1e-6;
        return {e};
    }
    // prism, lathe, sor: boxed by their curve points (the first and last points of quadratic
    // and cubic splines, and a sor's, only steer the curve), measured on linear, cubic,
    // conic and sor cases. A conic prism's outline is scaled by its larger height.
    ShapeBox operator()(const scene::Prism& p) const {
        const Extents r = curve_range(p.spline, p.points);
        const double top = std::max(std::abs(p.height1), std::abs(p.height2));
        const double k = p.conic ? top : 1;
        return {{{r.min.x * k, p.height1, r.min.y * k}, {r.max.x * k, p.height2, r.max.y * k}}};
    }
    ShapeBox operator()(const scene::Lathe& l) const {
        return {turned(curve_range(l.spline, l.points))};
    }
    ShapeBox operator()(const scene::Sor& s) const {
        std::vector<glm::dvec3> on;
        for (size_t i = 1; i + 1 < s.points.size(); ++i) on.emplace_back(s.points[i], 0);
        if (on.empty()) return {{glm::dvec3(0), glm::dvec3(0)}};
        return {turned(point_range(on, 0))};
    }
    static Extents curve_range(scene::SplineKind kind, const std::vector<glm::dvec2>& pts) {
        const size_t skip = kind == scene::SplineKind::Quadratic || kind == scene::SplineKind::Cubic;
        const size_t tail = kind == scene::SplineKind::Cubic;
        std::vector<glm::dvec3> on;
        for (size_t i = skip; i + tail < pts.size(); ++i) on.emplace_back(pts[i], 0);
        if (on.empty()) return {glm::dvec3(0), glm::dvec3(0)};
        return point_range(on, 0);
    }
    // A curve of <radius, height> points turned about y.
    static Extents turned(const Extents& r) {
        const double rmax = std::max(std::abs(r.min.x), std::abs(r.max.x));
        return {{-rmax, r.min.y, -rmax}, {rmax, r.max.y, rmax}};
    }
    // Unbounded like a plane unless clipped (POV-Ray's poly, cubic, quartic and quadric).
    ShapeBox operator()(const scene::Poly&) const { return {huge(), true}; }
    ShapeBox operator()(const scene::Quadric&) const { return {huge(), true}; }
    ShapeBox operator()(const scene::Superellipsoid&) const {
        return {{glm::dvec3(-1.0001), glm::dvec3(1.0001)}};
    }
    // POV-Ray's box: the widest of the spheres and the lemon's equator, from the bottom of
    // the bottom sphere to the top of the top one (measured).
    ShapeBox operator()(const scene::Ovus& v) const {
        const scene::Ovus::Lemon l = v.lemon();
        const double r = std::max({v.bottom, v.top, l.radius - l.offset});
        return {{{-r, -v.bottom, -r}, {r, v.bottom + v.top, r}}};
    }
    // POV-Ray's box: each element's bounding sphere in the element's own space (a sphere; a
    // cylinder's, centred on its axis and reaching its ends' rims; the end caps'), carried
    // into the blob's space as a sphere again: its box through the element's transform, then
    // the largest half-width of that box as the radius (measured: a scaled, rotated sphere
    // gets a cube). A cylinder's space turns z onto the axis by the smallest rotation.
    ShapeBox operator()(const scene::Blob& b) const {
        Extents out = empty_box();
        auto add = [&](const glm::dmat4& to_blob, bool exact, const glm::dvec3& centre, double r) {
            Extents e{centre - glm::dvec3(r), centre + glm::dvec3(r)};
            if (!exact) {
                e = corners(e, [&](const glm::dvec3& p) { return glm::dvec3(to_blob * glm::dvec4(p, 1)); });
                const glm::dvec3 half = 0.5 * (e.max - e.min), mid = 0.5 * (e.max + e.min);
                const double reach = std::max({half.x, half.y, half.z});
                e = {mid - glm::dvec3(reach), mid + glm::dvec3(reach)};
            }
            expand(out, e.min);
            expand(out, e.max);
        };
        for (const auto& c : b.components) {
            const glm::dmat4 placed = c.transform ? c.transform->m : glm::dmat4(1.0);
            if (!c.cylinder) {
                add(placed, !c.transform, c.a, c.radius);
                continue;
            }
            const double len = glm::length(c.b - c.a);
            const glm::dvec3 u = (c.b - c.a) / len;
            // The rotation taking z to the axis about their common perpendicular.
            const bool along_z = std::fabs(u.z) > 1 - 1e-10;
            const glm::dvec3 k = along_z ? glm::dvec3(1, 0, 0)
                                         : glm::normalize(glm::dvec3(-u.y, u.x, 0));
            const double cos_a = along_z ? (u.z < 0 ? -1 : 1) : u.z;
            const double sin_a = std::sqrt(std::max(0.0, 1 - cos_a * cos_a));
            glm::dmat4 frame(1.0);
            for (int col = 0; col < 3; ++col) {
                glm::dvec3 e(0);
                e[col] = 1;
                const glm::dvec3 r = cos_a * e + sin_a * glm::cross(k, e) +
                                     (1 - cos_a) * glm::dot(k, e) * k;
                frame[col] = glm::dvec4(r, 0);
            }
            frame[3] = glm::dvec4(c.a, 1);
            add(placed * frame, false, {0, 0, 0}, c.radius);
            add(placed * frame, false, {0, 0, len}, c.radius);
            add(placed * frame, false, {0, 0, 0.5 * len},
                std::sqrt(c.radius * c.radius + 0.25 * len * len));
        }
        return {out};
    }
    // The box POV-Ray searches: x and z over the grid, y from the water level (or the lowest
    // height) - 0.001 to the highest + 0.001, in the field's units (heights / 65536).
    ShapeBox operator()(const scene::HeightField& h) const {
        if (!h.heights || h.heights->empty()) return {{glm::dvec3(0), glm::dvec3(0)}};
        const auto [lo, hi] = std::minmax_element(h.heights->begin(), h.heights->end());
        // Water above every height leaves the two reversed: POV-Ray reports them swapped.
        const double y0 = std::max(double(*lo), 65536.0 * h.water_level) - 0.001, y1 = *hi + 0.001;
        return {{{0, std::min(y0, y1) / 65536.0, 0}, {1, std::max(y0, y1) / 65536.0, 1}}};
    }
    // POV-Ray's box about the bounding sphere.
    ShapeBox operator()(const scene::JuliaFractal& j) const {
        const double r = j.bound_radius();
        return {{glm::dvec3(-r), glm::dvec3(r)}};
    }
    // POV-Ray's box: the container's (a sphere's cube).
    ShapeBox operator()(const scene::Isosurface& s) const {
        return {{s.container.box_min(), s.container.box_max()}};
    }
    ShapeBox operator()(const scene::Parametric& s) const {
        return {{s.container.box_min(), s.container.box_max()}};
    }
    ShapeBox operator()(const scene::SphereSweep& s) const {
        Extents e;
        s.control_box(e.min, e.max);
        return {e};
    }
    ShapeBox operator()(const scene::Csg&) const { return {}; }
    ShapeBox operator()(const scene::UnsupportedShape& u) const {
        throw LumenError(u.what.loc, "'" + u.what.feature + "' is not supported yet");
    }
};

// An axis-aligned plane in `parent`'s frame as a half-space box, if it is one.
bool plane_half_space(const scene::Object& o, const scene::Transform& parent, bool inverted,
                      Extents& out) {
    const auto* p = std::get_if<scene::Plane>(&o.shape);
    if (!p) return false;
    const scene::Transform xf = o.transform.then(parent);
    glm::dvec3 n = xf.normal(p->normal);
    const double len = glm::length(n);
    if (!(len > 0)) return false;
    n /= len;
    const glm::dvec3 on = xf.point(p->normal * p->distance);
    out = huge();
    for (int a = 0; a < 3; ++a) {
        if (std::fabs(std::fabs(n[a]) - 1) > 1e-12) continue;
        const double d = on[a];
        if ((n[a] > 0) != inverted) out.max[a] = d;  // inside is where n·p <= d
        else out.min[a] = d;
        return true;
    }
    return false;
}

Extents box_of(const scene::Object& o, const scene::Transform& parent, int depth);

Extents csg_box(const scene::Csg& csg, const scene::Transform& parent, int depth) {
    const bool clips = csg.op == scene::CsgOp::Intersection || csg.op == scene::CsgOp::Difference;
    if (!clips) {
        Extents e = empty_box();
        for (const scene::ObjectPtr& c : csg.children) {
            if (!c) continue;
            const Extents b = box_of(*c, parent, depth + 1);
            expand(e, b.min);
            expand(e, b.max);
        }
        return e;
    }
    Extents e = huge();
    for (size_t i = 0; i < csg.children.size(); ++i) {
        const scene::ObjectPtr& c = csg.children[i];
        const bool inverted = (csg.op == scene::CsgOp::Difference && i > 0) != c->inverse;
        Extents b;
        if (plane_half_space(*c, parent, inverted, b) ||
            (!inverted && (b = box_of(*c, parent, depth + 1), true))) {
            const Extents cut = intersected(e, b);
            if (volume(cut) < volume(e) || i == 0) e = cut;
        }
    }
    return e;
}

Extents box_of(const scene::Object& o, const scene::Transform& parent, int depth) {
    if (depth > 1000) throw LumenError(o.loc, "objects are nested too deeply for min_extent");
    const scene::Transform xf = o.transform.then(parent);
    Extents e;
    if (const auto* csg = std::get_if<scene::Csg>(&o.shape)) {
        // POV-Ray transforms a CSG's box by its corners, not its children's boxes again.
        e = corners(csg_box(*csg, scene::Transform{}, depth), xf);
    } else {
        const ShapeBox b = std::visit(ShapeBoxes{xf}, o.shape);
        e = b.world ? b.box : corners(b.box, xf);
    }
    // clipped_by and bounded_by objects (in the parent's frame) replace a larger box.
    for (const auto* helpers : {&o.clipped_by, &o.bounded_by}) {
        if (helpers->empty()) continue;
        Extents h = huge();
        for (const scene::ObjectPtr& c : *helpers)
            if (c && !c->inverse) h = intersected(h, box_of(*c, parent, depth + 1));
        if (volume(h) < volume(e)) e = h;
    }
    return e;
}

}  // namespace

Extents object_extents(const scene::Object& object) {
    const Extents e = box_of(object, scene::Transform{}, 0);
    // POV-Ray stores a box as float lower-left corner and float lengths. The corner goes
    // through a volatile float: GCC 12 at -O3 stored x and y of it unrounded (measured:
    // box { -1.2, 1.2 } gave -1.2 where POV-Ray has -1.200000048).
    Extents out;
    for (int a = 0; a < 3; ++a) {
        volatile float lo = static_cast<float>(e.min[a]);
        const float len = static_cast<float>(e.max[a] - e.min[a]);
        out.min[a] = double(lo);
        out.max[a] = static_cast<float>(lo + len);
    }
    return out;
}

}  // namespace lumen::scene
