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
#include "render/shadows.hpp"
#include "render/surface_uv.hpp"
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
    static constexpr uint8_t kNoShadow = 1, kClear = 2;  // `hidden` bits
    Kind kind = Kind::Node;
    uint8_t hidden = 0;  // the queries that skip it: see hidden_bits()
    uint32_t node = 0;
    double min_depth = kDepthDefault;
    const void* shape = nullptr;  // the SphereShape, PlaneShape or BoxShape in the store
};

// The Root::hidden bits a query skips.
uint8_t hidden_bits(Query query) {
    static constexpr uint8_t bits[] = {0, Root::kNoShadow, Root::kNoShadow | Root::kClear};
    static_assert(int(Query::All) == 0 && int(Query::Shadow) == 1 &&
                  int(Query::ShadowSkipClear) == 2);
    return bits[int(query)];
}

// Every surface under node `index` lets light through unchanged (Intersector's clear objects).
bool clear_node(const NodeStore& store, uint32_t index) {
    const Node& n = store.nodes[index];
    if (n.kind == NodeKind::Shape) {
        // Mesh triangles may carry textures of their own.
        if (std::holds_alternative<MeshPtr>(store.shapes[n.shape])) return false;
        return passes_all_light(n.texture) &&
               (!n.interior_texture || passes_all_light(n.interior_texture)) &&
               clear_for_shadows(n.interior);
    }
    for (uint32_t i = 0; i < n.child_count; ++i)
        if (!clear_node(store, store.links[n.children + i])) return false;
    return true;
}

// Every surface under node `index` stops all light: no texture (a mesh triangle's or a blob
// component's included) has a layer that may let light through.
bool opaque_node(const NodeStore& store, uint32_t index) {
    const Node& n = store.nodes[index];
    if (n.kind != NodeKind::Shape) {
        for (uint32_t i = 0; i < n.child_count; ++i)
            if (!opaque_node(store, store.links[n.children + i])) return false;
        return true;
    }
    if (may_pass_light(n.texture) || may_pass_light(n.interior_texture)) return false;
    const ShapeData& d = store.shapes[n.shape];
    if (const auto* mesh = std::get_if<MeshPtr>(&d))
        for (const scene::LayeredTexture& t : (*mesh)->mesh.textures)
            if (may_pass_light(&t)) return false;
    if (const auto* blob = std::get_if<BlobShape>(&d))
        for (const scene::LayeredTexture* t : blob->textures)
            if (may_pass_light(t)) return false;
    return true;
}

// A bounded root's kind and flags (unbounded ones are never skipped as clear: no box can say
// where their surfaces are).
Root make_root(const NodeStore& store, uint32_t index, bool bounded) {
    Root r;
    r.node = index;
    const Node& n = store.nodes[index];
    r.hidden = (n.no_shadow ? Root::kNoShadow : 0) |
               (bounded && clear_node(store, index) ? Root::kClear : 0);
    if (n.kind != NodeKind::Shape || !n.identity || n.clip_count || n.bound_count) return r;
    const ShapeData& d = store.shapes[n.shape];
    if (auto* s = std::get_if<SphereShape>(&d)) r.kind = Root::Kind::Sphere, r.shape = s;
    else if (auto* s = std::get_if<PlaneShape>(&d)) r.kind = Root::Kind::Plane, r.shape = s;
    else if (auto* s = std::get_if<BoxShape>(&d)) r.kind = Root::Kind::Box, r.shape = s;
    r.min_depth = n.min_depth;
    return r;
}

// Same answer as intersect_node(store, r.node, ...) (its primitive path, for direct kinds).
// `local` is the world ray itself, made once per query; callers have skipped hidden roots.
bool intersect_root(const NodeStore& store, const Root& r, const Ray& ray, const LocalRay& local,
                    double tmin, double tmax, bool shadow, NodeHit& hit) {
    if (r.kind == Root::Kind::Node) return intersect_node(store, r.node, ray, tmin, tmax, shadow, hit);
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
    if (leaf.needs_uv) {
        const glm::dvec3 local =
            leaf.identity ? hit.point : store.transforms[leaf.xf].inv_point(hit.point);
        hit.uv = surface_uv(store.shapes[leaf.shape], local, hit.point, best.shape);
    }
    hit.object = leaf.object;
    hit.texture = best.shape.texture ? best.shape.texture : leaf.texture;
    hit.interior_texture = leaf.interior_texture;
    hit.interior = leaf.interior;
    // POV-Ray tells insides apart by their interior: the children of a CSG that share its
    // material are one inside (a ray passes from one into the next without leaving it).
    hit.interior_id = leaf.interior ? static_cast<const void*>(leaf.interior) : leaf.object;
    hit.no_image = leaf.no_image;
    hit.no_reflection = leaf.no_reflection;
    hit.double_illuminate = leaf.double_illuminate;
    hit.no_radiosity = leaf.no_radiosity;
    hit.hollow = leaf.hollow;
    hit.photons = leaf.photons;
    hit.photon_target = leaf.photon_target;
    hit.light_group = leaf.light_group;
    hit.global_lights = leaf.global_lights;
    hit.textured_blob = nullptr;
    if (leaf.kind == NodeKind::Shape) {
        const auto* blob = std::get_if<BlobShape>(&store.shapes[leaf.shape]);
        if (blob && blob->textured) {
            hit.textured_blob = blob;
            hit.local_point =
                leaf.identity ? hit.point : store.transforms[leaf.xf].inv_point(hit.point);
        }
    }
}

}  // namespace

struct Geometry::Impl {
    static constexpr int kQueries = 3;  // per Query value
    NodeStore store;
    std::vector<Root> bounded;        // roots in BVH order
    std::vector<Root> unbounded;      // roots tested by every ray
    std::vector<Aabb> bounded_boxes;  // bounded[i]'s box (small scenes skip the BVH walk)
    Aabb seen_bounded[kQueries];      // around the bounded roots each query sees
    Bvh bvh;
    size_t primitives = 0;
    std::vector<PlacedObject> placed;  // the roots in scene order
    std::vector<uint32_t> placed_nodes;  // their nodes
    bool listable[kQueries] = {};  // every root seen is a direct kind: visit_shadow_hits works
    bool mostly_passes_light[kQueries] = {};
    bool opaque_only[kQueries] = {};  // every root seen is an opaque_node
    // Boxes of the clear roots that shadow rays see, grown by twice the shadow tolerance, in
    // the order of clear_bvh.
    std::vector<Aabb> clear_boxes;
    Bvh clear_bvh;

    // Calls visit(root) for every root `query` sees that is unbounded or whose box the ray
    // may meet within [t_min, limit]; `limit` may shrink as visit finds hits.
    template <class Visit>
    void for_each_candidate(const Ray& ray, double t_min, const double& limit, Query query,
                            Visit&& visit) const {
        for_each_candidate(SlabRay(ray.origin, ray.dir), t_min, limit, query, visit);
    }
    template <class Visit>
    void for_each_candidate(const SlabRay& slab, double t_min, const double& limit, Query query,
                            Visit&& visit) const {
        const uint8_t hide = hidden_bits(query);
        for (const Root& r : unbounded)
            if (!(r.hidden & hide)) visit(r);
        const size_t n = bounded.size();
        if (n <= kDirectRoots) {
            // A handful of objects: past the box around them all (one test culls most shadow
            // rays), their own boxes cull as well as the BVH's inner nodes would.
            if (n && slab.hits(seen_bounded[int(query)], t_min, limit))
                for (size_t i = 0; i < n; ++i)
                    if (!(bounded[i].hidden & hide) && slab.hits(bounded_boxes[i], t_min, limit))
                        visit(bounded[i]);
        } else {
            double prune = limit;
            bvh.traverse(slab, t_min, prune, [&](uint32_t i) {
                if (bounded[i].hidden & hide) return;
                visit(bounded[i]);
                prune = limit;
            });
        }
    }

    // Occluder numbering: the unbounded roots, then the bounded ones.
    uint32_t root_number(const Root& r) const {
        const Root* p = &r;
        if (p >= unbounded.data() && p < unbounded.data() + unbounded.size())
            return uint32_t(p - unbounded.data());
        return uint32_t(unbounded.size() + (p - bounded.data()));
    }
    // The root an Occluder names, if `query` sees it and the ray may meet its box.
    const Root* hinted_root(uint32_t number, const SlabRay& slab, double t_min, double t_max,
                            Query query) const {
        const Root* r = nullptr;
        if (number < unbounded.size()) {
            r = &unbounded[number];
        } else if (number - unbounded.size() < bounded.size()) {
            const size_t i = number - unbounded.size();
            if (!slab.hits(bounded_boxes[i], t_min, t_max)) return nullptr;
            r = &bounded[i];
        }
        return r && !(r->hidden & hidden_bits(query)) ? r : nullptr;
    }

    // Per query: the box around the bounded roots it sees, whether they can all be listed,
    // and whether at least half of them may let light through.
    void summarise_queries() {
        for (Query q : {Query::All, Query::Shadow, Query::ShadowSkipClear}) {
            const int k = int(q);
            const uint8_t hide = hidden_bits(q);
            size_t seen = 0, passing_light = 0;
            listable[k] = opaque_only[k] = true;
            for (const auto* list : {&bounded, &unbounded})
                for (const Root& r : *list) {
                    if (r.hidden & hide) continue;
                    ++seen;
                    listable[k] = listable[k] && r.kind != Root::Kind::Node;
                    opaque_only[k] = opaque_only[k] && opaque_node(store, r.node);
                    const Node& n = store.nodes[r.node];
                    passing_light += may_pass_light(n.texture) || may_pass_light(n.interior_texture);
                }
            mostly_passes_light[k] = 2 * passing_light >= seen;
            for (size_t i = 0; i < bounded.size(); ++i)
                if (!(bounded[i].hidden & hide)) seen_bounded[k].expand(bounded_boxes[i]);
        }
    }

    void index_clear_roots() {
        std::vector<Aabb> boxes;
        for (size_t i = 0; i < bounded.size(); ++i)
            if (bounded[i].hidden == Root::kClear) {
                Aabb b = bounded_boxes[i];
                b.lo -= 2 * kShadowTolerance;
                b.hi += 2 * kShadowTolerance;
                boxes.push_back(b);
            }
        if (boxes.empty()) return;
        clear_bvh.build(boxes);
        for (uint32_t i : clear_bvh.order()) clear_boxes.push_back(boxes[i]);
    }
};

Geometry::Geometry(const std::vector<scene::ObjectPtr>& objects) : impl_(std::make_unique<Impl>()) {
    NodeStore& store = impl_->store;
    std::vector<uint32_t> roots;
    std::vector<scene::Transform> to_world;
    for (const auto& object : objects)
        if (object) compile_top_level(store, *object, roots, to_world);
    for (size_t i = 0; i < roots.size(); ++i) {
        const Node& n = store.nodes[roots[i]];
        impl_->placed.push_back({n.object, to_world[i], n.texture, n.kind != NodeKind::Shape,
                                 n.no_radiosity, n.clip_count > 0});
        impl_->placed_nodes.push_back(roots[i]);
    }
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
            impl_->unbounded.push_back(make_root(store, r, false));
        }
    }
    // One root a leaf, so a root is visited only by rays that cross its own box: a leaf of
    // two would pair a small object with a huge one (abyss.pov's media sphere, which every
    // ray enters) and take it into every ray.
    impl_->bvh.build(boxes, 1);
    for (uint32_t i : impl_->bvh.order()) {
        impl_->bounded.push_back(make_root(store, finite[i], true));
        impl_->bounded_boxes.push_back(boxes[i]);
    }
    impl_->summarise_queries();
    impl_->index_clear_roots();
}

Geometry::~Geometry() = default;

size_t Geometry::primitive_count() const { return impl_->primitives; }

const std::vector<PlacedObject>& Geometry::placed_objects() const { return impl_->placed; }

std::vector<Diagnostic> Geometry::shape_warnings() const {
    std::vector<Diagnostic> out;
    for (const Node& n : impl_->store.nodes) {
        if (n.kind != NodeKind::Shape) continue;
        if (const auto* iso = std::get_if<IsosurfaceShape>(&impl_->store.shapes[n.shape]))
            if (auto message = gradient_warning(*iso))
                out.push_back({Severity::Warning, n.object ? n.object->loc : SourceLoc{}, *message, {}, {}});
    }
    return out;
}

namespace {

bool closed_shape(const scene::Object& o) {
    const scene::Shape& s = o.shape;
    if (const auto* c = std::get_if<scene::Cylinder>(&s)) return !c->open;
    if (const auto* c = std::get_if<scene::Cone>(&s)) return !c->open;
    return std::holds_alternative<scene::Box>(s) || std::holds_alternative<scene::Sphere>(s) ||
           std::holds_alternative<scene::Torus>(s) || std::holds_alternative<scene::Plane>(s) ||
           std::holds_alternative<scene::Superellipsoid>(s) ||
           std::holds_alternative<scene::Ovus>(s);
}

// Appends the primitives under node `index`; false when one has no inside.
bool closed_leaves(const NodeStore& store, uint32_t index, std::vector<const scene::Object*>& out) {
    const Node& n = store.nodes[index];
    if (n.kind == NodeKind::Shape) {
        out.push_back(n.object);
        return n.object && closed_shape(*n.object);
    }
    for (uint32_t i = 0; i < n.child_count; ++i)
        if (!closed_leaves(store, store.links[n.children + i], out)) return false;
    return true;
}

}  // namespace

std::vector<const scene::Object*> Geometry::solid_primitives(const glm::dvec3& eye) const {
    std::vector<const scene::Object*> out;
    for (size_t i = 0; i < impl_->placed.size(); ++i) {
        if (!hides_inside(i, eye)) continue;
        const size_t mark = out.size();
        if (!closed_leaves(impl_->store, impl_->placed_nodes[i], out)) out.resize(mark);
    }
    return out;
}

bool Geometry::inside_placed(size_t i, const glm::dvec3& p) const {
    return inside_node(impl_->store, impl_->placed_nodes[i], p);
}

bool Geometry::placed_is_opaque(size_t i) const {
    const Node& n = impl_->store.nodes[impl_->placed_nodes[i]];
    return !n.no_image && !n.no_reflection && !may_pass_light(n.texture) &&
           !may_pass_light(n.interior_texture);
}

bool Geometry::intersect(const Ray& ray, double t_min, double t_max, Hit& hit, Query query) const {
    const NodeStore& store = impl_->store;
    const bool shadow = query != Query::All;
    const ShadowRayMark mark(shadow);  // isosurfaces' cross-ray cache
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
    impl_->for_each_candidate(ray, t_min, limit, query, test);
    if (!found) return false;

    resolve_hit(store, ray, best_t, best, hit);
    return true;
}

bool Geometry::opaque_only(Query query) const { return impl_->opaque_only[int(query)]; }

bool Geometry::occluded(const Ray& ray, double t_min, double t_max, Query query,
                        Occluder* last) const {
    const NodeStore& store = impl_->store;
    const LocalRay local{ray.origin, ray.dir};
    const ShadowRayMark mark(query != Query::All);  // isosurfaces' cross-ray cache
    auto blocks = [&](const Root& r) {
        NodeHit h;
        return r.kind == Root::Kind::Node
                   ? intersect_node(store, r.node, ray, t_min, t_max, true, h, true)
                   : intersect_root(store, r, ray, local, t_min, t_max, true, h);
    };
    const SlabRay slab(ray.origin, ray.dir);
    const Root* hinted = last ? impl_->hinted_root(last->root, slab, t_min, t_max, query) : nullptr;
    if (hinted && blocks(*hinted)) return true;
    const Root* found = nullptr;
    double limit = t_max;  // -inf once found: the BVH walk then meets no further box
    impl_->for_each_candidate(slab, t_min, limit, query, [&](const Root& r) {
        if (found || &r == hinted) return;
        if (blocks(r)) found = &r, limit = -Aabb::inf;
    });
    if (found && last) last->root = impl_->root_number(*found);
    return found != nullptr;
}

Intersector::Listing Geometry::shadow_listing(Query query) const {
    if (!impl_->listable[int(query)]) return Listing::Never;
    return impl_->mostly_passes_light[int(query)] ? Listing::FromStart : Listing::AfterFirstSurface;
}

bool Geometry::has_clear_objects() const { return !impl_->clear_boxes.empty(); }

bool Geometry::near_clear_object(const glm::dvec3& p) const {
    // A point query: the slab test of a ray from p over [0, 0] passes exactly the boxes
    // holding p.
    bool near = false;
    double reach = 0;
    impl_->clear_bvh.traverse(SlabRay(p, glm::dvec3(1)), 0, reach, [&](uint32_t i) {
        if (impl_->clear_boxes[i].contains(p)) near = true, reach = -1;
    });
    return near;
}

int Geometry::visit_shadow_hits(const Ray& ray, double t_min, double t_max, Query query,
                                HitVisitor visit, void* context) const {
    if (!impl_->listable[int(query)]) return -1;
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
    impl_->for_each_candidate(ray, t_min, t_max, query, collect);
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

InteriorList Geometry::interiors_around(const glm::dvec3& p) const {
    InteriorList out;
    const std::vector<PlacedObject>& placed = placed_objects();
    for (size_t i = 0; i < placed.size(); ++i) {
        const scene::Object* o = placed[i].object;
        if (!o || !inside_placed(i, p)) continue;
        const scene::Interior* in = o->interior ? &*o->interior : nullptr;
        out.push(in ? static_cast<const void*>(in) : o, in, o->hollow);
    }
    return out;
}

}  // namespace lumen::render
