#include "render/object_queries.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "render/geometry.hpp"

namespace lumen::render {
namespace {

// POV-Ray's trace() keeps the nearest hit at least this far along the ray (measured: a start
// 1e-5 above a plane misses it).
constexpr double kTraceMinDepth = 1e-4;
constexpr size_t kMaxCachedObjects = 256;

// `target`'s object -> world transform, found below `o`.
bool world_transform(const scene::Object& o, const scene::Object* target,
                     const scene::Transform& parent, scene::Transform& out) {
    const scene::Transform xf = o.transform.then(parent);
    if (&o == target) {
        out = xf;
        return true;
    }
    if (const auto* csg = std::get_if<scene::Csg>(&o.shape))
        for (const scene::ObjectPtr& c : csg->children)
            if (c && world_transform(*c, target, xf, out)) return true;
    return false;
}

// trace() reports the primitive's raw normal, which for these is the opposite of the outward
// normal lumen's hits carry (measured): flat triangles and meshes without normals (POV's
// winding), and the walls of text (POV's walls face into the glyph).
bool pov_flips_normal(const scene::Object& root, const render::Hit& hit) {
    if (!hit.object) return false;
    const scene::Shape& shape = hit.object->shape;
    if (const auto* t = std::get_if<scene::Triangle>(&shape)) return !t->smooth;
    if (const auto* m = std::get_if<scene::Mesh>(&shape))
        return std::all_of(m->faces.begin(), m->faces.end(),
                           [](const scene::Mesh::Face& f) { return f.n[0] < 0; });
    if (std::holds_alternative<scene::Text>(shape)) {
        scene::Transform xf;
        if (!world_transform(root, hit.object, scene::Transform{}, xf)) return false;
        const glm::dvec3 face = glm::normalize(xf.normal(glm::dvec3(0, 0, 1)));
        return std::fabs(glm::dot(face, hit.normal)) < 0.5;  // a wall, not a face
    }
    return false;
}

class GeometryQueries final : public scene::ObjectQueries {
public:
    std::optional<Hit> trace(const scene::ObjectPtr& object, const glm::dvec3& origin,
                             const glm::dvec3& dir) override {
        render::Hit hit;
        if (!geometry(object).intersect(Ray{origin, dir}, kTraceMinDepth, 1e300, hit))
            return std::nullopt;
        // 0 - n, not -n: a flipped zero component stays +0, as POV prints it.
        return Hit{hit.point, pov_flips_normal(*object, hit) ? glm::dvec3(0) - hit.normal : hit.normal};
    }
    bool inside(const scene::ObjectPtr& object, const glm::dvec3& p) override {
        return Geometry::inside(*object, p);
    }

private:
    struct Entry {
        scene::ObjectPtr object;  // keeps the key's object alive
        std::unique_ptr<Geometry> geometry;
    };
    const Geometry& geometry(const scene::ObjectPtr& object) {
        auto it = cache_.find(object.get());
        if (it != cache_.end()) return *it->second.geometry;
        if (cache_.size() >= kMaxCachedObjects) cache_.clear();
        auto g = std::make_unique<Geometry>(std::vector<scene::ObjectPtr>{object});
        return *cache_.emplace(object.get(), Entry{object, std::move(g)}).first->second.geometry;
    }
    std::unordered_map<const scene::Object*, Entry> cache_;
};

}  // namespace

std::shared_ptr<scene::ObjectQueries> make_object_queries() {
    return std::make_shared<GeometryQueries>();
}

}  // namespace lumen::render
