// Primitive meshing: every curved shape is a parametric grid (one code path); flat shapes are
// polygons subdivided in world space.
#include "render/radiosity/mesher.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <type_traits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "render/radiosity/ray_cast.hpp"

namespace lumen::render::radiosity {

namespace {

constexpr double two_pi = 2 * std::numbers::pi;

class Builder {
public:
    Builder(const scene::Transform& to_world, const MeshOptions& opt, const SurfaceProps& props)
        : xf_(to_world), opt_(opt), props_(props) {
        mirrored_ = glm::determinant(glm::dmat3(xf_.m)) < 0;
    }

    // A local-space polygon (front by the right-hand rule) subdivided in world space;
    // `texture`: a mesh face's texture_list entry.
    void polygon(const std::vector<glm::dvec3>& local, int texture = -1) {
        std::vector<glm::dvec3> world;
        for (const auto& p : local) world.push_back(xf_.point(p));
        world_polygon(std::move(world), false, texture);
    }

    // `oriented`: the front already faces the right way in world space (no mirror fix-up).
    void world_polygon(std::vector<glm::dvec3> world, bool oriented = false, int texture = -1) {
        if ((mirrored_ && !oriented) != opt_.inward) std::reverse(world.begin(), world.end());
        Patch p = make_patch(std::move(world), props_.rho, props_.emission, props_.object);
        p.texture = texture;
        if (p.degenerate()) return;
        for (auto& e : subdivide(p, opt_.max_edge))
            if (!e.degenerate()) out.push_back(std::move(e));
    }

    // Parametric surface f(s, t), s and t in [0, 1], front = ∂f/∂s × ∂f/∂t, split into
    // ns x nt quads; quads with a collapsed edge (poles, apexes) become triangles.
    void grid(const std::function<glm::dvec3(double, double)>& f, int ns, int nt) {
        for (int i = 0; i < ns; ++i)
            for (int j = 0; j < nt; ++j) {
                const glm::dvec3 corners[4] = {
                    xf_.point(f(double(i) / ns, double(j) / nt)),
                    xf_.point(f(double(i + 1) / ns, double(j) / nt)),
                    xf_.point(f(double(i + 1) / ns, double(j + 1) / nt)),
                    xf_.point(f(double(i) / ns, double(j + 1) / nt))};
                std::vector<glm::dvec3> v;
                for (const auto& c : corners) {
                    const double scale = std::max(1.0, glm::length(c));
                    if (v.empty() || glm::length(c - v.back()) > 1e-12 * scale) v.push_back(c);
                }
                if (v.size() > 1 && glm::length(v.front() - v.back()) <= 1e-12) v.pop_back();
                if (v.size() < 3) continue;
                if (mirrored_ != opt_.inward) std::reverse(v.begin(), v.end());
                const Patch p = make_patch(std::move(v), props_.rho, props_.emission,
                                           props_.object);
                if (!p.degenerate()) out.push_back(p);
            }
    }

    // Segments for a local length stretched by `stretch` into world space (at least 1, or
    // min_segments around a curve); by default the transform's largest stretch.
    int segments(double local_length, bool around, double stretch) const {
        int n = int(std::ceil(local_length * stretch / std::max(opt_.max_edge, 1e-9) - 1e-9));
        n = std::clamp(n, 1, 4096);
        return around ? std::max(n, opt_.min_segments) : n;
    }
    int segments(double local_length, bool around = false) const {
        return segments(local_length, around, max_stretch());
    }
    // The stretch along a local unit direction, and the largest within the plane of the
    // orthonormal u, w: a cylinder scaled only along its axis keeps its circles' segments
    // (patio-radio_36.pov's balcony discs, scaled 1020 along z, made 108,000 elements each).
    double stretch_along(const glm::dvec3& dir) const {
        return glm::length(glm::dmat3(xf_.m) * dir);
    }
    double stretch_in_plane(const glm::dvec3& u, const glm::dvec3& w) const {
        const glm::dmat3 m(xf_.m);
        const glm::dvec3 a = m * u, c = m * w;
        const double p = glm::dot(a, a), q = glm::dot(c, c), r = glm::dot(a, c);
        return std::sqrt((p + q) / 2 + std::hypot((p - q) / 2, r));
    }

    std::vector<Patch> out;

private:
    double max_stretch() const {
        const glm::dmat3 m(xf_.m);
        return std::max({glm::length(m[0]), glm::length(m[1]), glm::length(m[2])});
    }
    const scene::Transform& xf_;
    const MeshOptions& opt_;
    const SurfaceProps& props_;
    bool mirrored_ = false;
};

void mesh_box(const scene::Box& box, Builder& b) {
    const glm::dvec3 lo = glm::min(box.min, box.max), hi = glm::max(box.min, box.max);
    for (int a = 0; a < 3; ++a) {
        const int bb = (a + 1) % 3, c = (a + 2) % 3;  // e_b × e_c = e_a
        for (int side = 0; side < 2; ++side) {
            auto corner = [&](bool bhi, bool chi) {
                glm::dvec3 p;
                p[a] = side ? hi[a] : lo[a];
                p[bb] = bhi ? hi[bb] : lo[bb];
                p[c] = chi ? hi[c] : lo[c];
                return p;
            };
            std::vector<glm::dvec3> q = {corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)};
            if (!side) std::reverse(q.begin(), q.end());
            b.polygon(q);
        }
    }
}

void mesh_sphere(const scene::Sphere& s, Builder& b) {
    const int lat = std::max(4, b.segments(std::numbers::pi * s.radius));
    const int lon = std::max(2 * lat, b.segments(two_pi * s.radius, true));
    b.grid([&](double u, double v) {
        const double theta = -std::numbers::pi / 2 + std::numbers::pi * u, phi = two_pi * v;
        return s.center + s.radius * glm::dvec3(std::cos(theta) * std::cos(phi),
                                                std::sin(theta),
                                                std::cos(theta) * std::sin(phi));
    }, lat, lon);
}

void mesh_disc_at(const glm::dvec3& c, const glm::dvec3& n, double radius, double hole,
                  Builder& b) {
    glm::dvec3 u, w;
    tangent_frame(glm::normalize(n), u, w);
    const double inner = std::clamp(hole, 0.0, radius);
    const double stretch = b.stretch_in_plane(u, w);
    b.grid([&](double s, double t) {
        const double r = inner + (radius - inner) * s, phi = two_pi * t;
        return c + r * (std::cos(phi) * u + std::sin(phi) * w);
    }, b.segments(radius - inner, false, stretch), b.segments(two_pi * radius, true, stretch));
}

// Lateral surface of a cone frustum (a cylinder when the radii agree), plus its caps.
void mesh_cone(const glm::dvec3& base, double r0, const glm::dvec3& cap, double r1, bool open,
               Builder& b) {
    const glm::dvec3 axis = cap - base;
    const double len = glm::length(axis);
    if (!(len > 0)) return;
    const glm::dvec3 a = axis / len;
    glm::dvec3 u, w;
    tangent_frame(a, u, w);
    const double slant = std::hypot(len, r1 - r0);
    const double around = b.stretch_in_plane(u, w), along = b.stretch_along(a);
    b.grid([&](double s, double t) {
        const double phi = two_pi * s, r = r0 + (r1 - r0) * t;
        return base + t * axis + r * (std::cos(phi) * u + std::sin(phi) * w);
    }, b.segments(two_pi * std::max(r0, r1), true, around),
       b.segments(slant, false, r0 == r1 ? along : std::max(along, around)));
    if (open) return;
    if (r1 > 0) mesh_disc_at(cap, a, r1, 0, b);
    if (r0 > 0) mesh_disc_at(base, -a, r0, 0, b);
}

void mesh_torus(const scene::Torus& t, Builder& b) {
    b.grid([&](double s, double v) {
        const double psi = two_pi * s, phi = two_pi * v;
        const double ring = t.major + t.minor * std::cos(psi);
        return glm::dvec3(ring * std::cos(phi), t.minor * std::sin(psi), ring * std::sin(phi));
    }, b.segments(two_pi * t.minor, true), b.segments(two_pi * (t.major + t.minor), true));
}

// Clips a convex polygon to the half-space dot(n, p) <= d.
std::vector<glm::dvec3> clip(const std::vector<glm::dvec3>& poly, const glm::dvec3& n, double d) {
    std::vector<glm::dvec3> out;
    for (size_t i = 0; i < poly.size(); ++i) {
        const glm::dvec3 &p = poly[i], &q = poly[(i + 1) % poly.size()];
        const double dp = glm::dot(n, p) - d, dq = glm::dot(n, q) - d;
        if (dp <= 0) out.push_back(p);
        if ((dp <= 0) != (dq <= 0)) out.push_back(p + (dp / (dp - dq)) * (q - p));
    }
    return out;
}

void mesh_plane(const scene::Transform& to_world, const scene::Plane& pl, const MeshOptions& opt,
                Builder& b) {
    const glm::dvec3 n = glm::normalize(to_world.normal(pl.normal));
    const glm::dvec3 origin = to_world.point(pl.normal * pl.distance);
    glm::dvec3 u, w;
    tangent_frame(n, u, w);
    const glm::dvec3 centre = 0.5 * (opt.bounds_min + opt.bounds_max);
    const double half = glm::length(opt.bounds_max - opt.bounds_min) + 1;
    const glm::dvec3 c = centre - glm::dot(centre - origin, n) * n;  // centre on the plane
    std::vector<glm::dvec3> region = {c - half * u - half * w, c + half * u - half * w,
                                      c + half * u + half * w, c - half * u + half * w};
    for (int a = 0; a < 3; ++a) {
        glm::dvec3 e(0);
        e[a] = 1;
        region = clip(region, e, opt.bounds_max[a]);
        region = clip(region, -e, -opt.bounds_min[a]);
    }
    if (region.size() < 3) return;
    double u0 = INFINITY, u1 = -INFINITY, w0 = INFINITY, w1 = -INFINITY;
    for (const auto& p : region) {
        u0 = std::min(u0, glm::dot(p - c, u)), u1 = std::max(u1, glm::dot(p - c, u));
        w0 = std::min(w0, glm::dot(p - c, w)), w1 = std::max(w1, glm::dot(p - c, w));
    }
    glm::dvec3 inner(0);  // a point inside the convex region, to orient its edge normals
    for (const auto& p : region) inner += p / double(region.size());
    const double step = std::max(opt.max_edge, 1e-9);
    const int nu = std::clamp(int(std::ceil((u1 - u0) / step)), 1, 4096);
    const int nw = std::clamp(int(std::ceil((w1 - w0) / step)), 1, 4096);
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nw; ++j) {
            const double a0 = u0 + i * step, a1 = std::min(u1, a0 + step);
            const double b0 = w0 + j * step, b1 = std::min(w1, b0 + step);
            std::vector<glm::dvec3> cell = {c + a0 * u + b0 * w, c + a1 * u + b0 * w,
                                            c + a1 * u + b1 * w, c + a0 * u + b1 * w};
            // Keep the part of the cell inside the (convex) region: clip by each edge.
            for (size_t k = 0; k < region.size() && cell.size() >= 3; ++k) {
                const glm::dvec3 &p = region[k], &q = region[(k + 1) % region.size()];
                glm::dvec3 out_n = glm::cross(q - p, n);  // region is CCW about n
                if (glm::dot(out_n, inner - p) > 0) out_n = -out_n;
                cell = clip(cell, out_n, glm::dot(out_n, p));
            }
            if (cell.size() < 3) continue;
            b.world_polygon(std::move(cell), /*oriented=*/true);
        }
}

void mesh_polygon(const scene::Polygon& poly, Builder& b) {
    // Closed sub-polygons as written; each one is meshed separately (holes are not cut).
    const auto& pts = poly.points;
    size_t start = 0;
    while (start < pts.size()) {
        size_t end = start + 1;
        while (end < pts.size() && pts[end] != pts[start]) ++end;
        std::vector<glm::dvec3> loop(pts.begin() + start, pts.begin() + std::min(end, pts.size()));
        for (const auto& tri : triangulate(loop)) b.polygon({loop[tri[0]], loop[tri[1]], loop[tri[2]]});
        start = end + 1;
    }
}

void mesh_faces(const scene::Mesh& m, Builder& b) {
    const int n = int(m.vertices.size());
    for (const auto& f : m.faces) {
        if (f.v[0] < 0 || f.v[1] < 0 || f.v[2] < 0 || f.v[0] >= n || f.v[1] >= n || f.v[2] >= n)
            continue;
        // The face's texture as the renderer takes it: its first vertex's.
        const int texture = f.tex[0] >= 0 && size_t(f.tex[0]) < m.textures.size() ? f.tex[0] : -1;
        b.polygon({m.vertices[f.v[0]], m.vertices[f.v[1]], m.vertices[f.v[2]]}, texture);
    }
}

// What the mesher answers for a shape that gets no patches.
struct NotMeshed {};

// One case per scene shape and no catch-all: a listed shape (scene/shape_list.hpp) must be
// meshed here or declared NotMeshed.
struct ShapeMesher {
    const scene::Transform& to_world;
    const MeshOptions& opt;
    Builder& b;
    void operator()(const scene::Sphere& s) const { mesh_sphere(s, b); }
    void operator()(const scene::Plane& s) const { mesh_plane(to_world, s, opt, b); }
    void operator()(const scene::Box& s) const { mesh_box(s, b); }
    void operator()(const scene::Cylinder& s) const {
        mesh_cone(s.base, s.radius, s.cap, s.radius, s.open, b);
    }
    void operator()(const scene::Cone& s) const {
        mesh_cone(s.base, s.base_radius, s.cap, s.cap_radius, s.open, b);
    }
    void operator()(const scene::Torus& s) const { mesh_torus(s, b); }
    void operator()(const scene::Disc& s) const {
        mesh_disc_at(s.center, s.normal, s.radius, s.hole, b);
    }
    void operator()(const scene::Triangle& s) const { b.polygon({s.p[0], s.p[1], s.p[2]}); }
    void operator()(const scene::Polygon& s) const { mesh_polygon(s, b); }
    void operator()(const scene::Mesh& s) const { mesh_faces(s, b); }
    // Glyph outlines are not meshed: text only occludes.
    NotMeshed operator()(const scene::Text&) const { return {}; }
    // Swept splines are not meshed yet: they only occlude.
    NotMeshed operator()(const scene::Prism&) const { return {}; }
    NotMeshed operator()(const scene::Lathe&) const { return {}; }
    NotMeshed operator()(const scene::Sor&) const { return {}; }
    // Implicit surfaces are not meshed: they only occlude.
    NotMeshed operator()(const scene::Poly&) const { return {}; }
    NotMeshed operator()(const scene::Quadric&) const { return {}; }
    NotMeshed operator()(const scene::Superellipsoid&) const { return {}; }
    NotMeshed operator()(const scene::Blob&) const { return {}; }
    NotMeshed operator()(const scene::Ovus&) const { return {}; }
    NotMeshed operator()(const scene::Isosurface&) const { return {}; }
    NotMeshed operator()(const scene::Parametric&) const { return {}; }
    // Height fields are not meshed yet: they only occlude.
    NotMeshed operator()(const scene::HeightField&) const { return {}; }
    NotMeshed operator()(const scene::JuliaFractal&) const { return {}; }
    NotMeshed operator()(const scene::SphereSweep&) const { return {}; }
    // Unions are meshed through by the caller; other CSG only occludes.
    NotMeshed operator()(const scene::Csg&) const { return {}; }
    NotMeshed operator()(const scene::UnsupportedShape&) const { return {}; }
};

}  // namespace

std::vector<std::array<size_t, 3>> triangulate(const std::vector<glm::dvec3>& loop) {
    std::vector<std::array<size_t, 3>> tris;
    if (loop.size() < 3) return tris;
    glm::dvec3 normal(0);
    for (size_t i = 0; i < loop.size(); ++i)
        normal += glm::cross(loop[i], loop[(i + 1) % loop.size()]);
    if (!(glm::length(normal) > 0)) return tris;
    std::vector<size_t> idx(loop.size());
    for (size_t i = 0; i < idx.size(); ++i) idx[i] = i;
    auto convex = [&](size_t a, size_t b, size_t c) {
        return glm::dot(glm::cross(loop[b] - loop[a], loop[c] - loop[b]), normal) > 0;
    };
    auto inside = [&](size_t p, size_t a, size_t b, size_t c) {
        const glm::dvec3& x = loop[p];
        return glm::dot(glm::cross(loop[b] - loop[a], x - loop[a]), normal) >= 0 &&
               glm::dot(glm::cross(loop[c] - loop[b], x - loop[b]), normal) >= 0 &&
               glm::dot(glm::cross(loop[a] - loop[c], x - loop[c]), normal) >= 0;
    };
    size_t guard = 0;
    while (idx.size() > 3 && guard++ < 4 * loop.size() * loop.size()) {
        bool clipped = false;
        for (size_t k = 0; k < idx.size(); ++k) {
            const size_t a = idx[(k + idx.size() - 1) % idx.size()], b = idx[k],
                         c = idx[(k + 1) % idx.size()];
            if (!convex(a, b, c)) continue;
            bool ear = true;
            for (size_t q : idx)
                if (q != a && q != b && q != c && inside(q, a, b, c)) { ear = false; break; }
            if (!ear) continue;
            tris.push_back({a, b, c});
            idx.erase(idx.begin() + k);
            clipped = true;
            break;
        }
        if (!clipped) break;  // degenerate (collinear or self-intersecting): fan the rest
    }
    for (size_t k = 1; k + 1 < idx.size(); ++k) tris.push_back({idx[0], idx[k], idx[k + 1]});
    return tris;
}

bool meshable(const scene::Object& o) {
    return std::visit(
        [](const auto& s) {
            return !std::is_same_v<std::invoke_result_t<ShapeMesher, decltype(s)>, NotMeshed>;
        },
        o.shape);
}

std::vector<Patch> mesh_object(const scene::Object& o, const scene::Transform& to_world,
                               const MeshOptions& opt, const SurfaceProps& props) {
    Builder b(to_world, opt, props);
    std::visit<void>(ShapeMesher{to_world, opt, b}, o.shape);  // a NotMeshed answer adds nothing
    return std::move(b.out);
}

}  // namespace lumen::render::radiosity
