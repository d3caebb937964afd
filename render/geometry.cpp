// Geometry: the compiled nodes of the whole scene, a BVH over the bounded top-level nodes and
// a list of unbounded ones (planes, inverse shapes) that every ray tests.
#include "render/geometry.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include <glm/geometric.hpp>

#include "render/bvh.hpp"
#include "render/node.hpp"

namespace lumen::render {
namespace {

// std::nextafter(x, +inf) without the library call (it showed in profiles): for finite
// x >= 0 the next double up is the next bit pattern.
double next_up(double x) {
    if (!(x >= 0 && x < Aabb::inf)) return std::nextafter(x, Aabb::inf);
    return std::bit_cast<double>(std::bit_cast<uint64_t>(x) + 1);
}

// Up to this many bounded objects are tested in a loop instead of through the BVH.
constexpr size_t kDirectRoots = 8;

}  // namespace

struct Geometry::Impl {
    NodeStore store;
    std::vector<uint32_t> bounded;    // roots in BVH order
    std::vector<uint32_t> unbounded;  // roots tested by every ray
    std::vector<Aabb> bounded_boxes;  // bounded[i]'s box (small scenes skip the BVH walk)
    Aabb all_bounded;                 // around all of bounded_boxes
    Bvh bvh;
    size_t primitives = 0;
};

Geometry::Geometry(const scene::Scene& scene) : impl_(std::make_unique<Impl>()) {
    NodeStore& store = impl_->store;
    std::vector<uint32_t> roots;
    for (const auto& object : scene.objects)
        if (object) compile_top_level(store, *object, roots);
    std::vector<Aabb> boxes;
    std::vector<uint32_t> finite;
    for (uint32_t r : roots) {
        impl_->primitives += count_primitives(store, r);
        const Aabb& box = store.nodes[r].surface;
        if (box.empty()) continue;  // can never be hit
        if (box.finite()) {
            boxes.push_back(box);
            finite.push_back(r);
        } else {
            impl_->unbounded.push_back(r);
        }
    }
    impl_->bvh.build(boxes, 2);
    for (uint32_t i : impl_->bvh.order()) impl_->bounded.push_back(finite[i]);
    for (uint32_t r : impl_->bounded) {
        impl_->bounded_boxes.push_back(store.nodes[r].surface);
        impl_->all_bounded.expand(store.nodes[r].surface);
    }
}

Geometry::~Geometry() = default;

size_t Geometry::primitive_count() const { return impl_->primitives; }

bool Geometry::intersect(const Ray& ray, double t_min, double t_max, Hit& hit, bool shadow) const {
    const NodeStore& store = impl_->store;
    NodeHit best;
    bool found = false;
    double best_t = t_max;
    uint32_t best_root = std::numeric_limits<uint32_t>::max();
    // Limit for the next candidate: hits at exactly best_t still compete, and the earlier
    // object in scene order wins, so coincident surfaces resolve the same way on every ray.
    double limit = t_max;
    auto test = [&](uint32_t root) {
        NodeHit h;
        if (!intersect_node(store, root, ray, t_min, limit, shadow, h)) return;
        if (h.shape.t < best_t || (h.shape.t == best_t && root < best_root) || !found) {
            best = h;
            best_t = h.shape.t;
            best_root = root;
            found = true;
            limit = next_up(best_t);
        }
    };
    for (uint32_t r : impl_->unbounded) test(r);
    const SlabRay slab(ray.origin, ray.dir);
    if (impl_->bounded.size() <= kDirectRoots) {
        // A handful of objects: past the box around them all (one test culls most shadow
        // rays), their own boxes cull as well as the BVH's inner nodes would.
        if (!impl_->bounded.empty() && slab.hits(impl_->all_bounded, t_min, limit))
            for (size_t i = 0; i < impl_->bounded.size(); ++i)
                if (slab.hits(impl_->bounded_boxes[i], t_min, limit)) test(impl_->bounded[i]);
    } else {
        double prune = limit;
        impl_->bvh.traverse(slab, t_min, prune, [&](uint32_t i) {
            test(impl_->bounded[i]);
            prune = limit;
        });
    }
    if (!found) return false;

    const Node& leaf = store.nodes[best.leaf];
    hit.t = best_t;
    hit.point = ray.at(best_t);
    glm::dvec3 n = leaf.identity ? best.shape.normal
                                 : store.transforms[leaf.xf].normal(best.shape.normal);
    double len = glm::length(n);
    n = len > 0 && std::isfinite(len) ? n / len : glm::dvec3(0, 1, 0);
    hit.normal = leaf.flip ? -n : n;
    hit.uv = best.shape.uv;
    hit.object = leaf.object;
    hit.texture = best.shape.texture ? best.shape.texture : leaf.texture;
    hit.interior_texture = leaf.interior_texture;
    hit.interior = leaf.interior;
    hit.interior_id = leaf.object;
    hit.no_image = leaf.no_image;
    hit.no_reflection = leaf.no_reflection;
    hit.double_illuminate = leaf.double_illuminate;
    hit.no_radiosity = leaf.no_radiosity;
    return true;
}

bool Geometry::inside(const scene::Object& object, const glm::dvec3& p) {
    NodeStore store;
    uint32_t root = compile_object(store, object, NodeContext{}, false);
    return inside_node(store, root, p);
}

}  // namespace lumen::render
