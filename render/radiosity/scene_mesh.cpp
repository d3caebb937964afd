#include "render/radiosity/scene_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include "base/stop_request.hpp"
#include "render/radiosity/mesh_checks.hpp"
#include "render/radiosity/mesher.hpp"
#include "render/radiosity/surface_light.hpp"

namespace lumen::render::radiosity {

namespace {

// The objects the geometry compiled (unions flattened, so each carries the transform and
// texture it inherits) that get patches. The rest are lit where gather rays land on them
// (point_gather.hpp): no_radiosity objects are invisible to radiosity altogether. A clipped
// object is meshed whole: clipped_by only takes surface away, rays land only on what is left,
// and the elements of the rest are never reached (they cost a little time, nothing else).
std::vector<const PlacedObject*> meshed_objects(const Geometry& geometry) {
    std::vector<const PlacedObject*> out;
    for (const PlacedObject& p : geometry.placed_objects()) {
        const scene::Object& o = *p.object;
        if (p.no_radiosity || p.csg || !meshable(o) || never_diffuse(p.texture)) continue;
        out.push_back(&p);
    }
    return out;
}

void material_at(const scene::LayeredTexture* texture, const glm::dvec3& p,
                 const glm::dvec3& ambient, MeshVertex& v) {
    const SurfaceMaterial m = surface_material(texture, p, ambient);
    v.rho = m.rho;
    v.emission = m.emission;
    v.brilliance = m.brilliance;
}

// Vertices are shared by elements of the same texture and plane orientation.
using WeldKey = std::tuple<long long, long long, long long, int, int, int, const void*>;

class Welder {
public:
    Welder(SceneMesh& mesh, double quantum, const glm::dvec3& ambient)
        : mesh_(mesh), q_(quantum), ambient_(ambient) {}
    uint32_t vertex(const glm::dvec3& p, const glm::dvec3& n, const scene::LayeredTexture* t) {
        const WeldKey key{std::llround(p.x / q_), std::llround(p.y / q_), std::llround(p.z / q_),
                          int(std::lround(n.x * 1000)), int(std::lround(n.y * 1000)),
                          int(std::lround(n.z * 1000)), t};
        auto [it, inserted] = index_.try_emplace(key, uint32_t(mesh_.vertices.size()));
        if (inserted) {
            MeshVertex v;
            v.position = p;
            v.normal = n;
            material_at(t, p, ambient_, v);
            mesh_.vertices.push_back(v);
        }
        return it->second;
    }

private:
    SceneMesh& mesh_;
    double q_;
    glm::dvec3 ambient_;
    std::map<WeldKey, uint32_t> index_;
};

// The texture a patch shows: a mesh face's own (texture_list) or the object's.
const scene::LayeredTexture* patch_texture(const Patch& p, const PlacedObject& piece) {
    if (p.texture >= 0)
        if (const auto* m = std::get_if<scene::Mesh>(&piece.object->shape))
            return &m->textures[size_t(p.texture)];
    return piece.texture;
}

void add_patch(SceneMesh& mesh, Welder& welder, const Patch& p, const PlacedObject& piece) {
    const scene::LayeredTexture* texture = patch_texture(p, piece);
    // Quads and fans become triangles: values interpolate barycentrically.
    const size_t n = p.vertices.size();
    for (size_t k = 1; k + 1 < n; ++k) {
        const glm::dvec3 a = p.vertices[0], b = p.vertices[k], c = p.vertices[k + 1];
        const glm::dvec3 cr = glm::cross(b - a, c - a);
        const double len = glm::length(cr);
        if (!(len > 0)) continue;
        MeshElement e;
        e.normal = cr / len;
        e.area = 0.5 * len;
        e.object = piece.object;
        e.v = {welder.vertex(a, p.normal, texture), welder.vertex(b, p.normal, texture),
               welder.vertex(c, p.normal, texture)};
        mesh.elements.push_back(e);
    }
}

glm::ivec3 cell_of(const SceneMesh& m, const glm::dvec3& p) {
    return glm::clamp(glm::ivec3(glm::floor((p - m.grid_origin) / m.grid_cell)), glm::ivec3(0),
                      m.grid_size - 1);
}

size_t cell_index(const SceneMesh& m, const glm::ivec3& c) {
    return (size_t(c.z) * m.grid_size.y + c.y) * m.grid_size.x + c.x;
}

void build_frames(SceneMesh& m) {
    m.frames.reserve(m.elements.size());
    for (const MeshElement& e : m.elements) {
        SceneMesh::Frame f;
        f.a = m.vertices[e.v[0]].position;
        f.normal = e.normal;
        f.e1 = m.vertices[e.v[1]].position - f.a;
        f.e2 = m.vertices[e.v[2]].position - f.a;
        f.d11 = glm::dot(f.e1, f.e1);
        f.d12 = glm::dot(f.e1, f.e2);
        f.d22 = glm::dot(f.e2, f.e2);
        const double det = f.d11 * f.d22 - f.d12 * f.d12;
        f.inv_det = det > 0 ? 1 / det : 0;  // 0: degenerate, never contains a point
        m.frames.push_back(f);
    }
}

void build_grid(SceneMesh& m) {
    Aabb all;
    for (const Aabb& b : m.boxes) all.expand(b);
    if (all.empty()) return;
    const glm::dvec3 extent = all.hi - all.lo;
    // About one patch per cell, at most 128 cells along an axis.
    m.grid_cell = std::max({m.patch_size, extent.x / 128, extent.y / 128, extent.z / 128, 1e-9});
    m.grid_origin = all.lo;
    m.grid_size = glm::max(glm::ivec3(1), glm::ivec3(glm::ceil(extent / m.grid_cell)));
    const size_t cells = size_t(m.grid_size.x) * m.grid_size.y * m.grid_size.z;
    std::vector<uint32_t> count(cells + 1, 0);
    auto each_cell = [&](const Aabb& b, auto&& fn) {
        const glm::ivec3 lo = cell_of(m, b.lo), hi = cell_of(m, b.hi);
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x) fn(cell_index(m, {x, y, z}));
    };
    for (const Aabb& b : m.boxes) each_cell(b, [&](size_t c) { ++count[c + 1]; });
    for (size_t c = 0; c < cells; ++c) count[c + 1] += count[c];
    m.cell_start = count;
    m.cell_items.resize(count[cells]);
    m.cell_slots.resize(count[cells]);
    m.grid_bounds = all;
    for (uint32_t i = 0; i < m.boxes.size(); ++i) {
        const uint32_t slot = m.object_slot.at(m.elements[i].object);
        each_cell(m.boxes[i], [&](size_t c) {
            m.cell_slots[count[c]] = slot;
            m.cell_items[count[c]++] = i;
        });
    }
}

// Marks the vertex sides that face into their own opaque solid object with the eye outside
// it (the inner side of a box or sphere): no camera, reflection or gather ray reaches them,
// so they get no form factors and no gather.
void seal_sides(SceneMesh& mesh, const Geometry& geometry,
                const std::vector<const PlacedObject*>& pieces,
                const std::vector<size_t>& first_element, const glm::dvec3& eye) {
    const PlacedObject* placed = geometry.placed_objects().data();
    const double step = 1e-3 * mesh.patch_size;  // as gathers leave the surface
    std::vector<size_t> tested(mesh.vertices.size(), pieces.size());  // the last piece tested
    for (size_t k = 0; k < pieces.size(); ++k) {
        const size_t i = size_t(pieces[k] - placed);
        if (!geometry.hides_inside(i, eye)) continue;
        for (size_t e = first_element[k]; e < first_element[k + 1]; ++e)
            for (uint32_t v : mesh.elements[e].v) {
                if (tested[v] == k) continue;  // a vertex is shared by several elements
                tested[v] = k;
                MeshVertex& mv = mesh.vertices[v];
                for (uint32_t side = 0; side < 2; ++side) {
                    const glm::dvec3 n = side ? -mv.normal : mv.normal;
                    if (!(mv.sealed >> side & 1) &&
                        geometry.inside_placed(i, mv.position + step * (mv.inward + n)))
                        mv.sealed |= uint8_t(1u << side);
                }
            }
    }
}

}  // namespace

double default_patch_size(const Aabb& bounds) {
    if (bounds.empty() || !bounds.finite()) return 1.0;
    const double diagonal = glm::length(bounds.hi - bounds.lo);
    return diagonal > 0 ? diagonal / 38 : 1.0;
}

SceneMesh build_scene_mesh(const Geometry& geometry, double patch_size,
                           const glm::dvec3& ambient_emission, const glm::dvec3* eye) {
    SceneMesh mesh;
    const std::vector<const PlacedObject*> pieces = meshed_objects(geometry);

    // Finite shapes first: their extent bounds the infinite planes.
    MeshOptions opt;
    Aabb bounds;
    const double coarse = 1e30;  // one patch per face: only the extent matters here
    for (size_t i = 0; i < pieces.size(); ++i) {
        if (std::holds_alternative<scene::Plane>(pieces[i]->object->shape)) continue;
        opt.max_edge = coarse;
        for (const Patch& p : mesh_object(*pieces[i]->object, pieces[i]->to_world, opt, {}))
            for (const auto& v : p.vertices) bounds.expand(v);
    }
    if (bounds.empty()) bounds = {glm::dvec3(-10), glm::dvec3(10)};
    mesh.bounds = bounds;
    mesh.patch_size = patch_size > 0 ? patch_size : default_patch_size(bounds);
    const glm::dvec3 margin = 0.05 * (bounds.hi - bounds.lo) + glm::dvec3(mesh.patch_size);
    opt.bounds_min = bounds.lo - margin;
    opt.bounds_max = bounds.hi + margin;
    opt.max_edge = mesh.patch_size;

    Welder welder(mesh, mesh.patch_size * 1e-6, ambient_emission);
    std::vector<size_t> first_element;  // per piece
    for (const PlacedObject* piece : pieces) {
        throw_if_stop_requested();  // SIGINT/SIGTERM: a big scene meshes for a while
        first_element.push_back(mesh.elements.size());
        for (const Patch& p : mesh_object(*piece->object, piece->to_world, opt, {}))
            add_patch(mesh, welder, p, *piece);
    }
    first_element.push_back(mesh.elements.size());

    // Vertex areas and the direction into the adjacent elements (gathers start a hair inside
    // them, off shared edges and corners).
    for (const MeshElement& e : mesh.elements) {
        glm::dvec3 c(0);
        for (uint32_t v : e.v) c += mesh.vertices[v].position / 3.0;
        for (uint32_t v : e.v) {
            mesh.vertices[v].area += e.area / 3;
            mesh.vertices[v].inward += c - mesh.vertices[v].position;
        }
    }
    for (MeshVertex& v : mesh.vertices) {
        v.inward -= glm::dot(v.inward, v.normal) * v.normal;
        const double len = glm::length(v.inward);
        v.inward = len > 0 ? v.inward / len : glm::dvec3(0);
    }

    if (eye) {
        seal_sides(mesh, geometry, pieces, first_element, *eye);
        for (const scene::Object* o : geometry.solid_primitives(*eye)) mesh.solids.insert(o);
    }

    mesh.boxes.reserve(mesh.elements.size());
    for (const MeshElement& e : mesh.elements) {
        Aabb b;
        for (uint32_t v : e.v) b.expand(mesh.vertices[v].position);
        const glm::dvec3 pad(1e-7 * mesh.patch_size);
        mesh.boxes.push_back({b.lo - pad, b.hi + pad});
    }
    mesh.bvh.build(mesh.boxes);
    for (uint32_t i = 0; i < mesh.elements.size(); ++i) {
        auto [it, inserted] = mesh.object_slot.try_emplace(mesh.elements[i].object,
                                                           uint32_t(mesh.per_object.size()));
        if (inserted) mesh.per_object.emplace_back();
        mesh.per_object[it->second].elements.push_back(i);
    }
    build_frames(mesh);
    build_grid(mesh);
    // A side that faces into opaque matter (with the eye outside it) is seen by no ray; a
    // clipped object's matter may be seen through its cut.
    const double probe = 1e-4 * mesh.patch_size;
    std::vector<size_t> hiding;  // the objects whose matter no ray sees
    for (size_t i = 0; i < geometry.placed_objects().size(); ++i)
        if (!geometry.placed_objects()[i].clipped &&
            (eye ? geometry.hides_inside(i, *eye) : geometry.placed_is_opaque(i)))
            hiding.push_back(i);
    report_mesh_problems(mesh, mesh.warnings, [&](const glm::dvec3& p, const glm::dvec3& n) {
        return std::any_of(hiding.begin(), hiding.end(), [&](size_t i) {
            return geometry.inside_placed(i, p + probe * n);
        });
    });
    for (SceneMesh::ObjectElements& o : mesh.per_object) {
        std::vector<Aabb> boxes;
        for (uint32_t i : o.elements) boxes.push_back(mesh.boxes[i]);
        o.bvh.build(boxes);
    }
    return mesh;
}

long SceneMesh::find(const glm::dvec3& origin, const glm::dvec3& dir, double t, double slack,
                     const scene::Object* object, glm::dvec3& bary) const {
    const Bvh* tree = &bvh;
    const std::vector<uint32_t>* ids = nullptr;  // null: positions index `elements`
    if (object) {
        const auto slot = object_slot.find(object);
        if (slot == object_slot.end()) return -1;  // not meshed: the common miss, kept cheap
        tree = &per_object[slot->second].bvh;
        ids = &per_object[slot->second].elements;
        if (!cell_start.empty()) {
            const glm::dvec3 p = origin + t * dir;
            const double reach = std::max(slack, 0.5 * patch_size);
            if (glm::any(glm::lessThan(p, grid_bounds.lo - reach)) ||
                glm::any(glm::greaterThan(p, grid_bounds.hi + reach)))
                return -1;  // e.g. a plane's hit beyond its meshed part
            // The nearest element within half a patch (a curved surface lies up to a facet's
            // sagitta off its elements). Where it finds one, the ray's crossings of the
            // facets would miss the slack too; only a grid cell's edge can hide the right
            // element from it, so the tree below looks only when it finds none.
            const long near = find_near(p, slot->second, 0.5 * patch_size, bary);
            if (near >= 0) return near;
        }
    }
    long best = -1;
    double best_err = slack;
    double tmax = t + slack;
    const SlabRay ray(origin, dir);
    tree->traverse(ray, t - slack, tmax, [&](uint32_t pos) {
        const uint32_t k = tree->order()[pos];
        const uint32_t i = ids ? (*ids)[k] : k;
        const MeshElement& e = elements[i];
        if (object && e.object != object) return;
        const glm::dvec3 a = vertices[e.v[0]].position, b = vertices[e.v[1]].position,
                         c = vertices[e.v[2]].position;
        // Möller–Trumbore, both sides, edges included with a small tolerance.
        const glm::dvec3 e1 = b - a, e2 = c - a, pv = glm::cross(dir, e2);
        const double det = glm::dot(e1, pv);
        if (std::fabs(det) < 1e-300) return;
        const double inv = 1 / det;
        const glm::dvec3 tv = origin - a;
        const double u = glm::dot(tv, pv) * inv;
        const glm::dvec3 qv = glm::cross(tv, e1);
        const double w = glm::dot(dir, qv) * inv;
        constexpr double eps = 1e-6;
        if (u < -eps || w < -eps || u + w > 1 + eps) return;
        const double th = glm::dot(e2, qv) * inv;
        const double err = std::fabs(th - t);
        if (err > best_err) return;
        best_err = err;
        best = long(i);
        const double uc = std::clamp(u, 0.0, 1.0), wc = std::clamp(w, 0.0, 1.0 - uc);
        bary = {1 - uc - wc, uc, wc};
    });
    return best;
}

namespace {

// The elements of `tree` (over `ids`) whose box comes within `reach` of p along every axis.
void elements_near(const Bvh& tree, const std::vector<uint32_t>& ids,
                   const std::vector<Aabb>& boxes, const glm::dvec3& p, double reach,
                   std::vector<uint32_t>& out) {
    const std::vector<BvhNode>& nodes = tree.nodes();
    if (nodes.empty()) return;
    const Aabb probe{p - reach, p + reach};
    auto meets = [&](const Aabb& b) {
        return b.lo.x <= probe.hi.x && b.hi.x >= probe.lo.x && b.lo.y <= probe.hi.y &&
               b.hi.y >= probe.lo.y && b.lo.z <= probe.hi.z && b.hi.z >= probe.lo.z;
    };
    uint32_t stack[Bvh::kMaxDepth + 4];
    int sp = 0;
    stack[sp++] = 0;
    while (sp > 0) {
        const BvhNode& n = nodes[stack[--sp]];
        if (!meets(n.box)) continue;
        if (n.count) {
            for (uint32_t i = n.index, e = n.index + n.count; i < e; ++i) {
                const uint32_t element = ids[tree.order()[i]];
                if (meets(boxes[element])) out.push_back(element);
            }
        } else {
            stack[sp++] = n.index;
            stack[sp++] = uint32_t(&n - nodes.data()) + 1;
        }
    }
}

}  // namespace

long SceneMesh::find_near(const glm::dvec3& p, uint32_t slot, double slack,
                          glm::dvec3& bary) const {
    const glm::ivec3 cell = cell_of(*this, p);
    const size_t c = cell_index(*this, cell);
    // The element whose plane is nearest p among those in the cell whose projection holds p
    // (the last such in element order; the first at distance 0).
    long best = -1;
    double best_h = slack;
    auto consider = [&](uint32_t element) {
        const Frame& f = frames[element];
        const glm::dvec3 ap = p - f.a;
        const double along = glm::dot(ap, f.normal), h = std::fabs(along);
        if (h > best_h || f.inv_det == 0) return false;
        const glm::dvec3 r = ap - along * f.normal;
        const double r1 = glm::dot(r, f.e1), r2 = glm::dot(r, f.e2);
        const double u = (f.d22 * r1 - f.d12 * r2) * f.inv_det,
                     w = (f.d11 * r2 - f.d12 * r1) * f.inv_det;
        constexpr double eps = 1e-6;
        if (u < -eps || w < -eps || u + w > 1 + eps) return false;
        const double uc = std::clamp(u, 0.0, 1.0), wc = std::clamp(w, 0.0, 1.0 - uc);
        bary = {1 - uc - wc, uc, wc};
        best = long(element);
        best_h = h;
        return h == 0;
    };
    constexpr uint32_t kScanned = 64;  // cells this full are searched through the object's tree
    if (cell_start[c + 1] - cell_start[c] <= kScanned || slot >= per_object.size()) {
        for (uint32_t k = cell_start[c]; k < cell_start[c + 1]; ++k)
            if (cell_slots[k] == slot && consider(cell_items[k])) break;
        return best;
    }
    // A dense mesh puts hundreds of an object's elements in a cell. An element whose
    // projection holds p at plane distance h has its box within h of p (plus the projection
    // test's tolerance), so the elements with boxes near p give a first answer h1, and those
    // within h1 of p are all that can match or beat it: scanned in element order, as the
    // cell lists them, they give the cell scan's answer.
    const ObjectElements& own = per_object[slot];
    const double tolerance = 1e-5 * patch_size;
    thread_local std::vector<uint32_t> near;
    auto scan_within = [&](double reach) {
        near.clear();
        elements_near(own.bvh, own.elements, boxes, p, reach, near);
        std::sort(near.begin(), near.end());
        best = -1;
        best_h = slack;
        for (uint32_t element : near) {
            // Only elements listed in this cell: their box's cells include it.
            const glm::ivec3 lo = cell_of(*this, boxes[element].lo),
                             hi = cell_of(*this, boxes[element].hi);
            if (glm::any(glm::lessThan(cell, lo)) || glm::any(glm::greaterThan(cell, hi))) continue;
            if (consider(element)) break;
        }
    };
    scan_within(tolerance);
    // At distance 0 the second reach is the first's: the same elements, the same answer.
    if (best >= 0 && best_h == 0) return best;
    scan_within((best >= 0 ? best_h : slack) + tolerance);
    return best;
}

}  // namespace lumen::render::radiosity
