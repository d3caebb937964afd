// Geometry: the compiled nodes of the whole scene, a BVH over the bounded top-level nodes and
// a list of unbounded ones (planes, inverse shapes) that every ray tests.
#include "render/geometry.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

#include <glm/geometric.hpp>

#include "render/bvh.hpp"
#include "render/node.hpp"
#include "render/texture_layers.hpp"

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

// A top-level node as the nearest-hit loop sees it. World-space spheres, planes and boxes
// with no transform, clips or bounds (most roots of small scenes) are tested here directly:
// the node walk and variant dispatch cost more than the sphere test itself.
struct Root {
    enum class Kind : uint8_t { Node, Sphere, Plane, Box };
    Kind kind = Kind::Node;
    bool no_shadow = false;
    uint32_t node = 0;
    double min_depth = kDepthDefault;
    const void* shape = nullptr;  // the SphereShape, PlaneShape or BoxShape in the store
};

Root make_root(const NodeStore& store, uint32_t index) {
    Root r;
    r.node = index;
    const Node& n = store.nodes[index];
    if (n.kind != NodeKind::Shape || !n.identity || n.clip_count || n.bound_count) return r;
    const ShapeData& d = store.shapes[n.shape];
    if (auto* s = std::get_if<SphereShape>(&d)) r.kind = Root::Kind::Sphere, r.shape = s;
    else if (auto* s = std::get_if<PlaneShape>(&d)) r.kind = Root::Kind::Plane, r.shape = s;
    else if (auto* s = std::get_if<BoxShape>(&d)) r.kind = Root::Kind::Box, r.shape = s;
    r.no_shadow = n.no_shadow;
    r.min_depth = n.min_depth;
    return r;
}

// Same answer as intersect_node(store, r.node, ...) (its primitive path, for direct kinds).
// `local` is the world ray itself, made once per query.
bool intersect_root(const NodeStore& store, const Root& r, const Ray& ray, const LocalRay& local,
                    double tmin, double tmax, bool shadow, NodeHit& hit) {
    if (r.kind == Root::Kind::Node) return intersect_node(store, r.node, ray, tmin, tmax, shadow, hit);
    if (shadow && r.no_shadow) return false;
    const double from = std::max(tmin, r.min_depth);
    hit.leaf = r.node;
    if (r.kind == Root::Kind::Sphere)
        return intersect(*static_cast<const SphereShape*>(r.shape), local, from, tmax, hit.shape);
    if (r.kind == Root::Kind::Plane)
        return intersect(*static_cast<const PlaneShape*>(r.shape), local, from, tmax, hit.shape);
    return intersect(*static_cast<const BoxShape*>(r.shape), local, from, tmax, hit.shape);
}

// The Hit of a nearest-hit search's winner at distance t.
void resolve_hit(const NodeStore& store, const Ray& ray, double t, const NodeHit& best, Hit& hit) {
    const Node& leaf = store.nodes[best.leaf];
    hit.t = t;
    hit.point = ray.at(t);
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
}

}  // namespace

struct Geometry::Impl {
    NodeStore store;
    std::vector<Root> bounded;        // roots in BVH order
    std::vector<Root> unbounded;      // roots tested by every ray
    std::vector<Aabb> bounded_boxes;  // bounded[i]'s box (small scenes skip the BVH walk)
    Aabb all_bounded;                 // around all of bounded_boxes
    Bvh bvh;
    size_t primitives = 0;
    bool listable = true;  // every root is a direct kind: visit_shadow_hits works
    bool mostly_passes_light = false;

    // Calls visit(root) for every unbounded root and every bounded one whose box the ray may
    // meet within [t_min, limit]; `limit` may shrink as visit finds hits.
    template <class Visit>
    void for_each_candidate(const Ray& ray, double t_min, const double& limit, Visit&& visit) const {
        for (const Root& r : unbounded) visit(r);
        const SlabRay slab(ray.origin, ray.dir);
        const size_t n = bounded.size();
        if (n <= kDirectRoots) {
            // A handful of objects: past the box around them all (one test culls most shadow
            // rays), their own boxes cull as well as the BVH's inner nodes would.
            if (n && slab.hits(all_bounded, t_min, limit))
                for (size_t i = 0; i < n; ++i)
                    if (slab.hits(bounded_boxes[i], t_min, limit)) visit(bounded[i]);
        } else {
            double prune = limit;
            bvh.traverse(slab, t_min, prune, [&](uint32_t i) {
                visit(bounded[i]);
                prune = limit;
            });
        }
    }
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
            impl_->unbounded.push_back(make_root(store, r));
        }
    }
    impl_->bvh.build(boxes, 2);
    for (uint32_t i : impl_->bvh.order()) impl_->bounded.push_back(make_root(store, finite[i]));
    size_t roots_passing_light = 0;
    for (const auto* list : {&impl_->bounded, &impl_->unbounded})
        for (const Root& r : *list) {
            impl_->listable = impl_->listable && r.kind != Root::Kind::Node;
            const Node& n = store.nodes[r.node];
            roots_passing_light += may_pass_light(n.texture) || may_pass_light(n.interior_texture);
        }
    impl_->mostly_passes_light =
        2 * roots_passing_light >= impl_->bounded.size() + impl_->unbounded.size();
    for (const Root& r : impl_->bounded) {
        impl_->bounded_boxes.push_back(store.nodes[r.node].surface);
        impl_->all_bounded.expand(store.nodes[r.node].surface);
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
    const LocalRay local{ray.origin, ray.dir};
    auto test = [&](const Root& r) {
        const uint32_t root = r.node;
        NodeHit h;
        if (!intersect_root(store, r, ray, local, t_min, limit, shadow, h)) return;
        if (h.shape.t < best_t || (h.shape.t == best_t && root < best_root) || !found) {
            best = h;
            best_t = h.shape.t;
            best_root = root;
            found = true;
            limit = next_up(best_t);
        }
    };
    impl_->for_each_candidate(ray, t_min, limit, test);
    if (!found) return false;

    resolve_hit(store, ray, best_t, best, hit);
    return true;
}

bool Geometry::lists_shadow_hits() const { return impl_->listable; }
bool Geometry::mostly_passes_light() const { return impl_->mostly_passes_light; }

int Geometry::visit_shadow_hits(const Ray& ray, double t_min, double t_max, HitVisitor visit,
                                void* context) const {
    if (!impl_->listable) return -1;
    const NodeStore& store = impl_->store;
    struct Found {  // no default member values: the array is not cleared on every call
        double t;
        uint32_t root;
        glm::dvec3 normal;
        glm::dvec2 uv;
        const scene::LayeredTexture* texture;
    };
    static_assert(std::is_trivially_default_constructible_v<Found>);
    Found found[kMaxListedHits];
    int n = 0;
    bool overflow = false;
    const LocalRay local{ray.origin, ray.dir};
    // Plain spheres, planes and boxes report their next surface past `from` (each is crossed
    // at most twice), so a few calls per object list them all.
    auto collect = [&](const Root& r) {
        NodeHit h;
        for (double from = t_min; !overflow && intersect_root(store, r, ray, local, from, t_max, true, h);
             from = h.shape.t) {
            if (n == kMaxListedHits) overflow = true;
            else found[n++] = {h.shape.t, r.node, h.shape.normal, h.shape.uv, h.shape.texture};
        }
    };
    impl_->for_each_candidate(ray, t_min, t_max, collect);
    if (overflow) return -1;
    // Nearest first; at equal t the earlier object in scene order, as intersect() decides.
    int order[kMaxListedHits];
    for (int i = 0; i < n; ++i) {
        int j = i;
        for (; j > 0; --j) {
            const Found& a = found[order[j - 1]];
            if (a.t < found[i].t || (a.t == found[i].t && a.root < found[i].root)) break;
            order[j] = order[j - 1];
        }
        order[j] = i;
    }
    Hit hit;
    NodeHit winner;
    for (int i = 0; i < n; ++i) {
        const Found& f = found[order[i]];
        winner.leaf = f.root;  // a direct root is its own leaf
        winner.shape.t = f.t;
        winner.shape.normal = f.normal;
        winner.shape.uv = f.uv;
        winner.shape.texture = f.texture;
        resolve_hit(store, ray, f.t, winner, hit);
        if (!visit(context, hit)) return i + 1;
    }
    return n;
}

bool Geometry::inside(const scene::Object& object, const glm::dvec3& p) {
    NodeStore store;
    uint32_t root = compile_object(store, object, NodeContext{}, false);
    return inside_node(store, root, p);
}

}  // namespace lumen::render
