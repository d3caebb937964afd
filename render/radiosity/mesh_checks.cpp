#include "render/radiosity/mesh_checks.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>
#include <unordered_map>
#include <utility>

#include <glm/geometric.hpp>

#include "base/stop_request.hpp"

namespace lumen::render::radiosity {
namespace {

std::string where(const scene::Object* o) { return o ? o->loc.str() + ": " : std::string(); }

// Source order, so that a pair is always named the same way round.
bool earlier(const scene::Object* a, const scene::Object* b) {
    if (!a || !b) return a < b;
    return std::tie(a->loc.line, a->loc.column) < std::tie(b->loc.line, b->loc.column);
}

glm::dvec3 corner(const SceneMesh& m, const MeshElement& e, int k) {
    return m.vertices[e.v[k]].position;
}

bool is_sliver(const SceneMesh& m, const MeshElement& e) {
    double longest2 = 0;
    for (int k = 0; k < 3; ++k) {
        const glm::dvec3 d = corner(m, e, (k + 1) % 3) - corner(m, e, k);
        longest2 = std::max(longest2, glm::dot(d, d));
    }
    return longest2 > kSliverRatio * e.area;
}

// Whether p (on the element's plane) lies strictly inside it, with a margin of `inset`.
bool contains(const SceneMesh& m, const MeshElement& e, const glm::dvec3& p, double inset) {
    for (int k = 0; k < 3; ++k) {
        const glm::dvec3 a = corner(m, e, k), b = corner(m, e, (k + 1) % 3);
        const glm::dvec3 edge = b - a;
        const glm::dvec3 in = glm::normalize(glm::cross(e.normal, edge));  // points inside
        if (glm::dot(p - a, in) <= inset) return false;
    }
    return true;
}

// Mean reflectance and emission over the element's corners.
std::pair<glm::dvec3, glm::dvec3> material(const SceneMesh& m, const MeshElement& e) {
    glm::dvec3 rho(0), emission(0);
    for (uint32_t v : e.v) {
        rho += m.vertices[v].rho / 3.0;
        emission += m.vertices[v].emission / 3.0;
    }
    return {rho, emission};
}

// Coincident surfaces of one material (the overlapping boxes of a union, say) look and light
// the same whichever a ray meets: not worth a warning.
bool same_material(const SceneMesh& m, const MeshElement& e, const MeshElement& f) {
    const auto [rho_e, em_e] = material(m, e);
    const auto [rho_f, em_f] = material(m, f);
    const glm::dvec3 d = glm::abs(rho_e - rho_f) + glm::abs(em_e - em_f);
    return std::max({d.x, d.y, d.z}) < 1e-6;
}

struct CellKey {
    long x, y, z;
    bool operator==(const CellKey&) const = default;
};
struct CellHash {
    size_t operator()(const CellKey& k) const {
        return size_t(k.x) * 73856093u ^ size_t(k.y) * 19349663u ^ size_t(k.z) * 83492791u;
    }
};

void report_slivers(const SceneMesh& m, std::vector<std::string>& warnings) {
    std::map<const scene::Object*, int> count;
    for (const MeshElement& e : m.elements)
        if (is_sliver(m, e)) ++count[e.object];
    for (const auto& [object, n] : count)
        warnings.push_back(where(object) + "warning: radiosity: " + std::to_string(n) +
                           " sliver element(s) on this object (thinner than 1/500 of their "
                           "length); their indirect light is less reliable");
}

void report_coincident(const SceneMesh& m, std::vector<std::string>& warnings,
                       const HiddenSide& hidden) {
    // Each element goes into every cell its box (SceneMesh::boxes) overlaps; an element can cover another's
    // centroid only if it is listed in the centroid's cell. The cells are about the mean
    // element's size (at least 1/16 of a patch), so a crowd of small elements (a detailed
    // model) does not pile into one patch-wide cell and make the check quadratic.
    std::vector<glm::dvec3> centroid(m.elements.size());
    double mean_extent = 0;
    for (uint32_t i = 0; i < m.elements.size(); ++i) {
        const MeshElement& e = m.elements[i];
        centroid[i] = (corner(m, e, 0) + corner(m, e, 1) + corner(m, e, 2)) / 3.0;
        const glm::dvec3 d = m.boxes[i].hi - m.boxes[i].lo;
        mean_extent += std::max({d.x, d.y, d.z}) / double(m.elements.size());
    }
    const double cell = std::max({mean_extent, m.patch_size / 16, 1e-9});
    auto key = [&](const glm::dvec3& p) {
        return CellKey{long(std::floor(p.x / cell)), long(std::floor(p.y / cell)),
                       long(std::floor(p.z / cell))};
    };
    const double plane_tol = 1e-6 * std::max(m.patch_size, 1e-9);
    std::unordered_map<CellKey, std::vector<uint32_t>, CellHash> cells;
    for (uint32_t i = 0; i < m.elements.size(); ++i) {
        if (i % 4096 == 0) throw_if_stop_requested();
        const CellKey a = key(m.boxes[i].lo - plane_tol), b = key(m.boxes[i].hi + plane_tol);
        for (long z = a.z; z <= b.z; ++z)
            for (long y = a.y; y <= b.y; ++y)
                for (long x = a.x; x <= b.x; ++x) cells[{x, y, z}].push_back(i);
    }
    std::map<std::pair<const scene::Object*, const scene::Object*>, bool> pairs;
    for (uint32_t i = 0; i < m.elements.size(); ++i) {
        if (i % 4096 == 0) throw_if_stop_requested();
        const MeshElement& e = m.elements[i];
        const auto it = cells.find(key(centroid[i]));
        if (it == cells.end()) continue;
        for (uint32_t j : it->second) {
            const MeshElement& f = m.elements[j];
            if (f.object == e.object || glm::dot(e.normal, f.normal) < 1 - 1e-9) continue;
            const double off = glm::dot(centroid[i] - corner(m, f, 0), f.normal);
            if (std::fabs(off) > plane_tol) continue;
            if (!contains(m, f, centroid[i], plane_tol)) continue;
            if (same_material(m, e, f)) continue;
            const auto objects = earlier(e.object, f.object) ? std::pair(e.object, f.object)
                                                             : std::pair(f.object, e.object);
            if (pairs.count(objects) || (hidden && hidden(centroid[i], e.normal))) continue;
            pairs[objects] = true;
        }
    }
    std::vector<std::pair<const scene::Object*, const scene::Object*>> sorted;
    for (const auto& [objects, _] : pairs) sorted.push_back(objects);
    auto place = [](const scene::Object* o) {
        return o ? std::tuple(o->loc.line, o->loc.column) : std::tuple(0u, 0u);
    };
    std::sort(sorted.begin(), sorted.end(), [&](const auto& a, const auto& b) {
        return std::tuple(place(a.first), place(a.second)) <
               std::tuple(place(b.first), place(b.second));
    });
    std::set<std::string> said;  // objects made in a loop share their location: say it once
    for (const auto& objects : sorted) {
        std::string text = where(objects.first) + "warning: radiosity: this surface coincides " +
                           "with the one at " + (objects.second ? objects.second->loc.str()
                                                                 : std::string("?")) +
                           " (coplanar, overlapping, facing the same way); each point gets "
                           "the light of whichever a ray meets first";
        if (said.insert(text).second) warnings.push_back(std::move(text));
    }
}

}  // namespace

void report_mesh_problems(const SceneMesh& mesh, std::vector<std::string>& warnings,
                          const HiddenSide& hidden) {
    report_slivers(mesh, warnings);
    report_coincident(mesh, warnings, hidden);
}

}  // namespace lumen::render::radiosity
