// mesh / mesh2: triangles in a per-mesh BVH; per-face textures and smooth normals are looked
// up from the source mesh only for the final hit. Inside only with inside_vector: the parity
// of the surface crossings along it.
#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

#include <glm/geometric.hpp>

#include "render/shapes/mesh.hpp"

namespace lumen::render {

namespace {

bool valid_index(int i, size_t size) { return i >= 0 && size_t(i) < size; }

// Calls visit(position) for every triangle whose BVH leaf the ray reaches (all of them when
// the mesh was built without a BVH).
template <class Visit>
void for_candidates(const MeshShape& s, const LocalRay& r, double tmin, double& tmax,
                    Visit&& visit) {
    if (s.bvh.empty()) {
        for (uint32_t i = 0; i < s.tris.size(); ++i) visit(i);
        return;
    }
    s.bvh.traverse(SlabRay(r.o, r.d), tmin, tmax, visit);
}

// The corners' uvs blended by the hit's barycentric weights ((0, 0) without uvs); a
// bicubic_patch's (patch u, patch v) then lands bilinearly on its texture corners s0..s3.
glm::dvec2 face_uv(const scene::Mesh& m, const scene::Mesh::Face& face, double b1, double b2) {
    if (!valid_index(face.uv[0], m.uvs.size()) || !valid_index(face.uv[1], m.uvs.size()) ||
        !valid_index(face.uv[2], m.uvs.size()))
        return glm::dvec2(0);
    const glm::dvec2 uv = (1 - b1 - b2) * m.uvs[face.uv[0]] + b1 * m.uvs[face.uv[1]] +
                          b2 * m.uvs[face.uv[2]];
    if (m.patch_corners.size() != 4) return uv;
    const std::vector<glm::dvec2>& s = m.patch_corners;
    const glm::dvec2 low = s[0] + uv.y * (s[1] - s[0]), high = s[3] + uv.y * (s[2] - s[3]);
    return low + uv.x * (high - low);
}

}  // namespace

MeshPtr make_mesh(const scene::Mesh& m, MeshTraversal traversal) {
    auto out = std::make_shared<MeshShape>();
    out->mesh = m;
    std::vector<TriangleCore> tris;
    std::vector<uint32_t> faces;
    std::vector<uint32_t> corners;  // each triangle's vertex indices
    tris.reserve(m.faces.size());
    faces.reserve(m.faces.size());
    corners.reserve(3 * m.faces.size());
    for (size_t f = 0; f < m.faces.size(); ++f) {
        const auto& v = m.faces[f].v;
        if (!valid_index(v[0], m.vertices.size()) || !valid_index(v[1], m.vertices.size()) ||
            !valid_index(v[2], m.vertices.size()))
            continue;
        TriangleCore tri;
        if (!make_triangle_core(m.vertices[v[0]], m.vertices[v[1]], m.vertices[v[2]], tri))
            continue;  // degenerate faces are skipped
        tris.push_back(tri);
        faces.push_back(uint32_t(f));
        for (int i = 0; i < 3; ++i) {
            corners.push_back(uint32_t(v[i]));
            out->box.expand(m.vertices[v[i]]);
        }
    }
    out->valid = !tris.empty();
    if (traversal == MeshTraversal::Best && tris.size() >= kEmbreeMinTriangles) {
        out->embree = EmbreeMesh::build(m.vertices, corners, tris);
        if (out->embree) {  // its planes answer for the triangles
            out->face = std::move(faces);
            return out;
        }
    }
    if (traversal != MeshTraversal::Scan && !tris.empty()) {
        // The triangles' boxes only here: a mesh Embree takes never needs them.
        std::vector<Aabb> boxes(tris.size());
        for (size_t t = 0; t < tris.size(); ++t)
            for (int i = 0; i < 3; ++i) boxes[t].expand(m.vertices[corners[3 * t + size_t(i)]]);
        Bvh binary;
        binary.build(boxes, 4);
        out->bvh = WideBvh(binary);
        out->tris.reserve(tris.size());
        out->face.reserve(tris.size());
        for (uint32_t i : binary.order()) {
            out->tris.push_back(tris[i]);
            out->face.push_back(faces[i]);
        }
    } else {
        out->tris = std::move(tris);
        out->face = std::move(faces);
    }
    return out;
}

// Copies of a mesh share its vertices, faces, normals, uvs and textures (scene::SharedVector),
// and with them one prepared mesh: a hundred copies of a 20,000-triangle mesh build one tree,
// not a hundred. The table holds each prepared mesh weakly, by where its bulk lives; the
// shape keeps that bulk alive, so an address in the table cannot be reused while it is.
MeshPtr shared_mesh(const scene::Mesh& m, MeshTraversal traversal) {
    struct Key {
        const void *vertices, *normals, *uvs, *faces, *textures;
        MeshTraversal traversal;
        auto operator<=>(const Key&) const = default;
    };
    const Key key{m.vertices.identity(), m.normals.identity(), m.uvs.identity(),
                  m.faces.identity(),    m.textures.identity(), traversal};
    if (!key.faces) return make_mesh(m, traversal);
    static std::mutex mutex;
    static std::map<Key, std::weak_ptr<const MeshShape>> table;
    static size_t swept_at = 64;
    const std::lock_guard lock(mutex);
    std::weak_ptr<const MeshShape>& entry = table[key];
    if (MeshPtr s = entry.lock())
        if (s->mesh.inside_vector == m.inside_vector && s->mesh.patch_corners == m.patch_corners) return s;
    MeshPtr s = make_mesh(m, traversal);
    entry = s;
    if (table.size() >= 2 * swept_at) {  // forget meshes no longer in use, now and then
        std::erase_if(table, [](const auto& e) { return e.second.expired(); });
        swept_at = std::max<size_t>(64, table.size());
    }
    return s;
}

bool intersect(const MeshShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h) {
    if (!s.valid) return false;
    int best = -1;
    double best_u = 0, best_v = 0;
    glm::dvec3 normal;  // e1 x e2: need not be unit (ShapeHit)
    if (s.embree) {
        EmbreeMesh::Found f;
        if (!s.embree->nearest(r, tmin, tmax, f)) return false;
        best = int(f.tri), best_u = f.u, best_v = f.v, tmax = f.t, normal = f.normal;
    } else {
        for_candidates(s, r, tmin, tmax, [&](uint32_t i) {
            double t, u, v;
            if (hit_triangle(s.tris[i], r, tmin, tmax, t, u, v)) {
                tmax = t;  // prunes the rest of the traversal
                best = int(i);
                best_u = u;
                best_v = v;
            }
        });
        if (best < 0) return false;
        normal = glm::cross(s.tris[best].e1, s.tris[best].e2);
    }
    const scene::Mesh& m = s.mesh;
    h.t = tmax;
    h.normal = normal;
    h.uv = glm::dvec2(0);
    h.texture = nullptr;
    // A bare mesh's faces hold nothing more: skip loading its face (a cache miss per
    // incoherent ray in a big mesh).
    if (m.normals.empty() && m.uvs.empty() && m.textures.empty()) return true;
    const scene::Mesh::Face& face = m.faces[s.face[best]];
    if (valid_index(face.n[0], m.normals.size()) && valid_index(face.n[1], m.normals.size()) &&
        valid_index(face.n[2], m.normals.size())) {
        const glm::dvec3 flat = glm::normalize(h.normal);
        std::array<glm::dvec3, 3> n;
        for (int i = 0; i < 3; ++i) {
            double len = glm::length(m.normals[face.n[i]]);
            n[i] = len > 0 && std::isfinite(len) ? m.normals[face.n[i]] / len : flat;
        }
        h.normal = blend_normals(n, flat, best_u, best_v);
    }
    h.uv = face_uv(m, face, best_u, best_v);
    h.texture = valid_index(face.tex[0], m.textures.size()) ? &m.textures[face.tex[0]] : nullptr;
    return true;
}

bool any_hit(const MeshShape& s, const LocalRay& r, double tmin, double tmax, double& t) {
    if (!s.valid) return false;
    if (s.embree) {
        EmbreeMesh::Found f;
        if (!s.embree->any(r, tmin, tmax, f)) return false;
        t = f.t;
        return true;
    }
    bool found = false;
    for_candidates(s, r, tmin, tmax, [&](uint32_t i) {
        double u, v;
        if (!found && hit_triangle(s.tris[i], r, tmin, tmax, t, u, v)) {
            found = true;
            tmax = -Aabb::inf;  // the traversal meets no further box
        }
    });
    return found;
}

bool inside(const MeshShape& s, const glm::dvec3& p) {
    if (!s.valid || !s.mesh.inside_vector || !s.box.contains(p)) return false;
    LocalRay r{p, *s.mesh.inside_vector};
    if (r.d == glm::dvec3(0)) return false;
    if (s.embree) return s.embree->crossings(r) % 2 == 1;
    double tmax = Aabb::inf;
    int crossings = 0;
    for_candidates(s, r, 0.0, tmax, [&](uint32_t i) {
        double t, u, v;
        if (hit_triangle(s.tris[i], r, 0.0, Aabb::inf, t, u, v, 0)) ++crossings;
    });
    return crossings % 2 == 1;
}

Aabb bounds(const MeshShape& s) { return s.valid ? s.box : Aabb{}; }

}  // namespace lumen::render
