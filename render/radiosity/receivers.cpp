#include "render/radiosity/receivers.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "render/radiosity/scene_solution.hpp"

namespace lumen::render::radiosity {

namespace {

// A midpoint that a neighbour's split does not provide: its value is its edge's average.
constexpr uint32_t kImplied = std::numeric_limits<uint32_t>::max();

uint64_t edge_key(uint32_t a, uint32_t b) {
    if (a > b) std::swap(a, b);
    return uint64_t(a) << 32 | b;
}

double largest(const glm::dvec3& v) { return std::max({v.x, v.y, v.z}); }

}  // namespace

ReceiverMesh::ReceiverMesh(const SceneMesh& mesh) : mesh_(mesh) {
    const size_t n = mesh.vertices.size();
    positions_.reserve(n);
    normals_.reserve(n);
    origins_.reserve(n);
    for (const MeshVertex& v : mesh.vertices) {
        positions_.push_back(v.position);
        normals_.push_back(v.normal);
        origins_.push_back(gather_origin(mesh, v));
    }
    objects_.assign(n, nullptr);
    for (const MeshElement& e : mesh.elements)
        for (uint32_t v : e.v) objects_[v] = e.object;
    reach_.assign(n, 1e-2 * mesh.patch_size);  // corners lie on the surface
    G.assign(2 * n, glm::dvec3(0));
    known.assign(2 * n, 0);
    leaves.reserve(mesh.elements.size());
    for (const MeshElement& e : mesh.elements) leaves.push_back({e.v, 0, 0});
}

uint32_t ReceiverMesh::midpoint(uint32_t a, uint32_t b, uint32_t c) {
    const auto [it, inserted] = midpoints_.try_emplace(edge_key(a, b), uint32_t(positions_.size()));
    if (!inserted) return it->second;
    const glm::dvec3 p = 0.5 * (positions_[a] + positions_[b]);
    glm::dvec3 n = normals_[a] + normals_[b];
    n = glm::length(n) > 0 ? glm::normalize(n) : normals_[a];
    // Gathers start a hair inside the triangle being split (off its edge).
    glm::dvec3 in = positions_[c] - p;
    in -= glm::dot(in, n) * n;
    const double len = glm::length(in);
    in = len > 0 ? in / len : glm::dvec3(0);
    positions_.push_back(p);
    normals_.push_back(n);
    origins_.push_back(p + in * (1e-3 * mesh_.patch_size));
    objects_.push_back(objects_[a]);
    // A chord of an arc of up to 90 degrees is at most 0.21 of its length off the arc.
    reach_.push_back(0.5 * glm::length(positions_[b] - positions_[a]));
    for (uint32_t side = 0; side < 2; ++side) {
        G.push_back(0.5 * (G[2 * a + side] + G[2 * b + side]));
        known.push_back(known[2 * a + side] && known[2 * b + side]);
    }
    return it->second;
}

bool ReceiverMesh::covers(long element, uint32_t side) const {
    for (uint32_t v : mesh_.elements[size_t(element)].v)
        if (!known[2 * v + side]) return false;
    return true;
}

glm::dvec3 ReceiverMesh::value(long element, const glm::dvec3& bary, uint32_t side) const {
    std::array<uint32_t, 3> v = mesh_.elements[size_t(element)].v;
    std::array<glm::dvec3, 3> g;
    for (int k = 0; k < 3; ++k) g[k] = G[2 * v[k] + side];
    glm::dvec3 b = bary;
    for (int depth = 0; depth < 40 && !midpoints_.empty(); ++depth) {
        // m[k]: the midpoint of edge (v[k], v[k+1]), real or implied by its edge.
        std::array<uint32_t, 3> m;
        std::array<glm::dvec3, 3> gm;
        bool any = false;
        for (int k = 0; k < 3; ++k) {
            const uint32_t p = v[k], q = v[(k + 1) % 3];
            m[k] = kImplied;
            if (p != kImplied && q != kImplied)
                if (const auto it = midpoints_.find(edge_key(p, q)); it != midpoints_.end())
                    m[k] = it->second;
            any = any || m[k] != kImplied;
            gm[k] = m[k] != kImplied ? G[2 * m[k] + side] : 0.5 * (g[k] + g[(k + 1) % 3]);
        }
        if (!any) break;
        // The child holding b: the corner triangles (a, ab, ca), (ab, b, bc), (ca, bc, c) or
        // the middle one (bc, ca, ab), with b in its barycentrics.
        if (b.x >= 0.5) {
            v = {v[0], m[0], m[2]};
            g = {g[0], gm[0], gm[2]};
            b = {2 * b.x - 1, 2 * b.y, 2 * b.z};
        } else if (b.y >= 0.5) {
            v = {m[0], v[1], m[1]};
            g = {gm[0], g[1], gm[1]};
            b = {2 * b.x, 2 * b.y - 1, 2 * b.z};
        } else if (b.z >= 0.5) {
            v = {m[2], m[1], v[2]};
            g = {gm[2], gm[1], g[2]};
            b = {2 * b.x, 2 * b.y, 2 * b.z - 1};
        } else {
            v = {m[1], m[2], m[0]};
            g = {gm[1], gm[2], gm[0]};
            b = {1 - 2 * b.x, 1 - 2 * b.y, 1 - 2 * b.z};
        }
    }
    return b.x * g[0] + b.y * g[1] + b.z * g[2];
}

void fill_buried(const std::vector<ReceiverMesh::Triangle>& leaves, std::vector<glm::dvec3>& G,
                 std::vector<char>& buried, const std::vector<char>* known) {
    if (std::find(buried.begin(), buried.end(), 1) == buried.end()) return;
    for (int ring = 0; ring < 3; ++ring) {
        std::vector<glm::dvec3> sum(G.size(), glm::dvec3(0));
        std::vector<int> count(G.size(), 0);
        for (const ReceiverMesh::Triangle& t : leaves)
            for (uint32_t side = 0; side < 2; ++side)
                for (int a = 0; a < 3; ++a) {
                    const size_t u = 2 * size_t(t.v[a]) + side;
                    if (!buried[u]) continue;
                    for (int b = 0; b < 3; ++b) {
                        const size_t w = 2 * size_t(t.v[b]) + side;
                        if (b != a && !buried[w] && (!known || (*known)[w]))
                            sum[u] += G[w], ++count[u];
                    }
                }
        bool changed = false;
        for (size_t u = 0; u < G.size(); ++u)
            if (buried[u] && count[u] > 0) {
                G[u] = sum[u] / double(count[u]);
                buried[u] = 0;
                changed = true;
            }
        if (!changed) return;
    }
}

std::vector<glm::dvec3> smooth(const std::vector<ReceiverMesh::Triangle>& triangles,
                               const std::vector<glm::dvec3>& G, const std::vector<char>* known) {
    std::vector<glm::dvec3> sum(G.size(), glm::dvec3(0));
    std::vector<double> weight(G.size(), 0.0);
    for (const ReceiverMesh::Triangle& t : triangles)
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                for (uint32_t side = 0; side < 2; ++side) {
                    if (a != b && known && !(*known)[2 * t.v[b] + side]) continue;
                    const double w = a == b ? 1.0 : 0.5;  // a vertex is in several triangles
                    sum[2 * t.v[a] + side] += w * G[2 * t.v[b] + side];
                    weight[2 * t.v[a] + side] += w;
                }
    std::vector<glm::dvec3> out(G.size());
    for (size_t u = 0; u < G.size(); ++u) out[u] = weight[u] > 0 ? sum[u] / weight[u] : G[u];
    return out;
}

namespace {

// The point of triangle abc nearest to p (Ericson, Real-Time Collision Detection, 5.1.5).
glm::dvec3 nearest_on_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                               const glm::dvec3& c) {
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
        return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
    const double denom = va + vb + vc;
    if (!(denom > 0)) return a;  // degenerate
    return a + ab * (vb / denom) + ac * (vc / denom);
}

// A vertex side whose gather started this much inside solid matter is buried: what it
// gathered is not the light outside.
constexpr double kBuried = 0.9;

// How far a triangle's corners disagree, in units of the split threshold (> 1: split).
double disagreement(const ReceiverMesh::Triangle& t, const std::vector<glm::dvec3>& S,
                    const std::vector<char>& known, double tolerance, double floor) {
    double worst = 0;
    for (uint32_t side = 0; side < 2; ++side) {
        if (!(t.sides >> side & 1)) continue;
        for (int k = 0; k < 3; ++k) {
            const size_t p = 2 * t.v[k] + side, q = 2 * t.v[(k + 1) % 3] + side;
            if (!known[p] || !known[q]) continue;
            const glm::dvec3& a = S[p];
            const glm::dvec3& b = S[q];
            const double allowed = tolerance * (0.5 * (largest(a) + largest(b)) + floor);
            if (allowed > 0) worst = std::max(worst, largest(glm::abs(a - b)) / allowed);
        }
    }
    return worst;
}

}  // namespace

ReceiverMesh receive(const scene::Scene& scene, const SceneMesh& mesh,
                     const Intersector& geometry, const std::vector<glm::dvec3>& B,
                     const std::vector<char>& wanted, int rays, int threads,
                     const std::vector<glm::dvec3>& fallback,
                     const SubdivisionOptions& options, const SurfaceRadiance* unmeshed) {
    ReceiverMesh r(mesh);
    if (!fallback.empty()) {
        r.G = fallback;
        r.known.assign(r.G.size(), 1);
    } else {
        // ρ = 0: no light is ever reflected, so G = 0 is as good as any (the form factors
        // skip these too).
        for (uint32_t u = 0; u < mesh.unknowns(); ++u)
            r.known[u] = !needs_light(mesh.vertices[u / 2]);
    }
    std::vector<char> buried(r.G.size(), 0);
    auto gather = [&](const std::vector<uint32_t>& unknowns) {
        buried.resize(r.G.size(), 0);
        // Each worker with a fixed share and caches of its own: the gathers' values do not
        // depend on which thread reached a surface first.
        parallel_for_dealt(unknowns.size(), threads, [&](size_t worker, size_t begin, size_t end) {
            const auto chunk = [&] {
                for (size_t i = begin; i < end; ++i) {
                    const uint32_t u = unknowns[i], v = u / 2;
                    // From the true surface, about its normal: a gather from a curved shape's
                    // chord starts inside the shape, and one about the chord's normal sends rays
                    // into it.
                    glm::dvec3 origin = r.origin(v), n = r.normal(v);
                    onto_surface(geometry, r.object(v), origin, n, r.reach(v));
                    if (u % 2) n = -n;
                    const GatherResult g = gather_point(scene, mesh, geometry, B, origin, n, rays,
                                                        side_seed(u), unmeshed);
                    r.G[u] = g.G;
                    r.known[u] = 1;
                    buried[u] = g.inside >= kBuried;
                }
            };
            if (unmeshed) unmeshed->with_worker_caches(worker, chunk);
            else chunk();
        });
    };
    std::vector<uint32_t> todo;
    std::vector<uint8_t> done(mesh.vertices.size(), 0);  // bit s: side s gathered
    for (uint32_t u = 0; u < mesh.unknowns(); ++u)
        if (wanted[u] && needs_light(mesh.vertices[u / 2]) && !(mesh.vertices[u / 2].sealed >> (u % 2) & 1)) {
            todo.push_back(u);
            done[u / 2] |= uint8_t(1u << (u % 2));
        }
    gather(todo);
    fill_buried(r.leaves, r.G, buried, &r.known);
    for (ReceiverMesh::Triangle& t : r.leaves)
        for (uint32_t v : t.v) t.sides |= done[v];

    const size_t budget = size_t(std::max(0.0, options.budget) * double(todo.size()));
    size_t widened = 0;  // vertices added by splits of elements seen too wide: not budgeted
    const double min_edge = options.min_element > 0 ? options.min_element : mesh.patch_size / 8;
    for (int level = 0; options.enabled && level < 16; ++level) {
        // Decide on smoothed values: the raw ones carry the per-vertex ray noise.
        const std::vector<glm::dvec3> S = smooth(r.leaves, r.G, &r.known);
        double mean = 0;
        for (uint32_t u : todo) mean += largest(S[u]);
        const double floor = todo.empty() ? 0 : 0.1 * mean / double(todo.size());
        std::vector<std::pair<double, size_t>> marks;  // (disagreement, leaf), worst first
        for (size_t i = 0; i < r.leaves.size(); ++i) {
            const ReceiverMesh::Triangle& t = r.leaves[i];
            if (!t.sides) continue;
            double longest = 0;
            for (int k = 0; k < 3; ++k)
                longest = std::max(longest, glm::length(r.position(t.v[k]) -
                                                        r.position(t.v[(k + 1) % 3])));
            if (options.pixel_angle > 0 && options.max_span > 0 && options.image_width > 0) {
                // Seen too wide: split before anything else, outside the budget (the image
                // bounds how many such splits there can be).
                const glm::dvec3 a = r.position(t.v[0]), b = r.position(t.v[1]),
                                 c = r.position(t.v[2]);
                const glm::dvec3 near = nearest_on_triangle(options.eye, a, b, c);
                const double pixel = options.pixel_offset +
                                     options.pixel_angle * glm::length(near - options.eye);
                auto in_view = [&](const glm::dvec3& p) {
                    const glm::dvec3 d = p - options.eye;
                    const double len = glm::length(d);
                    return len > 0 && glm::dot(d, options.view_dir) >= options.view_cos * len;
                };
                // The seen elements themselves, and those of their pieces still in view (the
                // rest of a large element may reach far outside the image).
                if (longest > options.max_span * options.image_width * pixel &&
                    (t.depth == 0 || options.view_cos >= 1 || in_view(near) || in_view(a) ||
                     in_view(b) || in_view(c) || in_view((a + b + c) / 3.0))) {
                    marks.emplace_back(INFINITY, i);
                    continue;
                }
            }
            if (longest / 2 < min_edge) continue;
            if (options.pixel_angle > 0) {
                const glm::dvec3 centre =
                    (r.position(t.v[0]) + r.position(t.v[1]) + r.position(t.v[2])) / 3.0;
                const double pixel = options.pixel_offset +
                                     options.pixel_angle * glm::length(centre - options.eye);
                if (longest < options.min_pixels * pixel) continue;
            }
            const double d = disagreement(t, S, r.known, options.tolerance, floor);
            if (d > 1) marks.emplace_back(d, i);
        }
        std::sort(marks.begin(), marks.end(), std::greater<>());
        std::vector<char> split(r.leaves.size(), 0);
        std::vector<ReceiverMesh::Triangle> children;
        std::vector<uint32_t> fresh;
        for (const auto& [d, i] : marks) {
            if (d != INFINITY && r.added_vertices() - widened + 3 > budget) break;
            const ReceiverMesh::Triangle t = r.leaves[i];
            const auto [a, b, c] = t.v;
            const size_t before = r.added_vertices();
            const uint32_t ab = r.midpoint(a, b, c), bc = r.midpoint(b, c, a),
                           ca = r.midpoint(c, a, b);
            if (d == INFINITY) widened += r.added_vertices() - before;
            done.resize(r.vertex_count(), 0);
            for (uint32_t m : {ab, bc, ca})
                for (uint32_t side = 0; side < 2; ++side)
                    if ((t.sides >> side & 1) && !(done[m] >> side & 1)) {
                        fresh.push_back(2 * m + side);
                        done[m] |= uint8_t(1u << side);
                    }
            const uint8_t depth = uint8_t(t.depth + 1);
            children.push_back({{a, ab, ca}, t.sides, depth});
            children.push_back({{ab, b, bc}, t.sides, depth});
            children.push_back({{ca, bc, c}, t.sides, depth});
            children.push_back({{bc, ca, ab}, t.sides, depth});
            split[i] = 1;
            ++r.split;
        }
        if (children.empty()) break;
        std::vector<ReceiverMesh::Triangle> next;
        next.reserve(r.leaves.size() + children.size());
        for (size_t i = 0; i < r.leaves.size(); ++i)
            if (!split[i]) next.push_back(r.leaves[i]);
        next.insert(next.end(), children.begin(), children.end());
        r.leaves = std::move(next);
        gather(fresh);
        fill_buried(r.leaves, r.G, buried, &r.known);
    }
    r.G = smooth(r.leaves, r.G, &r.known);
    return r;
}

}  // namespace lumen::render::radiosity
