// Intersection and inside tests over compiled nodes: primitives, union, merge, intersection
// (difference = intersection with inverted subtrahends), clipped_by and bounded_by.
// CSG hits are found by asking each child for its nearest hit and, when the operation rejects
// it, asking again from just beyond it: no hit lists, no allocation. Nested CSG asks its inner
// nodes again and again along the same ray; a small per-thread table remembers each one's last
// answer (see NodeMemo).
#include <array>
#include <atomic>
#include <cmath>

#include "render/node.hpp"

namespace lumen::render {

namespace {

// Rejected hits one child may produce along a ray before it is given up on: a guard against
// a root finder that returns the same surface again an ulp further on, forever.
constexpr int kMaxRejected = 1024;

bool inside_all(const NodeStore& store, uint32_t first, uint32_t count, const glm::dvec3& p) {
    for (uint32_t i = 0; i < count; ++i)
        if (!inside_node(store, store.links[first + i], p)) return false;
    return true;
}

// bounded_by: the object counts only for rays that meet every bound or start inside it, as
// POV-Ray tests its bounding objects (`bounded_by { clipped_by }` over a cylinder and two
// planes bounds by their intersection, not by whichever plane a ray crosses).
bool ray_meets_bounds(const NodeStore& store, const Node& n, const Ray& ray) {
    for (uint32_t i = 0; i < n.bound_count; ++i) {
        uint32_t b = store.links[n.bounds + i];
        NodeHit h;
        if (!inside_node(store, b, ray.origin) &&  // the cheaper test first
            !intersect_node(store, b, ray, 0.0, Aabb::inf, false, h))
            return false;
    }
    return true;
}

// Whether a hit of child `which` at p survives the CSG operation of node n.
bool csg_accepts(const NodeStore& store, const Node& n, uint32_t which, const glm::dvec3& p) {
    for (uint32_t j = 0; j < n.child_count; ++j) {
        if (j == which) continue;
        bool in = inside_node(store, store.links[n.children + j], p);
        if (n.kind == NodeKind::Merge ? in : !in) return false;
    }
    return true;
}

// Nearest hit of a Shape node, ignoring its clipped_by and bounded_by.
// `any`: some hit will do (only its distance is set), which a mesh finds sooner.
inline bool intersect_primitive(const NodeStore& store, const Node& n, uint32_t index,
                                const Ray& ray, double tmin, double tmax, bool shadow,
                                NodeHit& hit, bool any = false) {
    if (shadow && n.no_shadow) return false;
    LocalRay local{ray.origin, ray.dir};
    if (!n.identity) {
        const scene::Transform& xf = store.transforms[n.xf];
        local = {xf.inv_point(ray.origin), xf.inv_vector(ray.dir)};
    }
    if (any)
        if (const auto* mesh = std::get_if<MeshPtr>(&store.shapes[n.shape])) {
            hit.leaf = index;
            return any_hit(**mesh, local, std::max(tmin, n.min_depth), tmax, hit.shape.t);
        }
    if (!shape_intersect(store.shapes[n.shape], local, std::max(tmin, n.min_depth), tmax,
                         hit.shape))
        return false;
    hit.leaf = index;
    return true;
}

// A node's last nearest-hit answer on a ray. The nearest hit t in (from, tmax) is also the
// nearest in (from', tmax') for any from <= from' < t (a hit if t < tmax', else none), and "no
// hit in (from, tmax)" holds for any narrower range: so a retry from a rejected hit, which asks
// the members again from further on, gets the members' answers without tracing them again
// (advanced/grenadine's lemon slice asked its prisms 230 times a ray). Exact: the answer is
// the one a new trace would give.
struct NodeMemo {
    uint64_t store = 0;  // the store's serial
    uint32_t index = 0;
    bool shadow = false, found = false;
    glm::dvec3 origin{0}, dir{0};
    double from = 0, tmax = 0;
    NodeHit hit;

    bool same_query(const NodeStore& s, uint32_t i, const Ray& ray, bool sh) const {
        return store == s.serial && index == i && shadow == sh && origin == ray.origin &&
               dir == ray.dir;
    }
    // Whether the answer for (tmin, tmax') is known, and then the answer.
    bool answers(double tmin, double t_max, bool& result, NodeHit& out) const {
        if (!(from <= tmin)) return false;
        if (found) {
            if (!(tmin < hit.shape.t)) return false;
            result = hit.shape.t < t_max;
            if (result) out = hit;
            return true;
        }
        if (!(t_max <= tmax)) return false;
        result = false;
        return true;
    }
};

NodeMemo& memo_slot(uint32_t index) {
    thread_local std::array<NodeMemo, 256> table;
    return table[index & 255];
}

// A CSG member's nearest hit, from the member's memo where it holds the answer.
bool intersect_member(const NodeStore& store, uint32_t index, const Ray& ray, double tmin,
                      double tmax, bool shadow, NodeHit& hit, bool any) {
    if (any) return intersect_node(store, index, ray, tmin, tmax, shadow, hit, true);
    bool result = false;
    if (NodeMemo& memo = memo_slot(index);
        memo.same_query(store, index, ray, shadow) && memo.answers(tmin, tmax, result, hit))
        return result;
    result = intersect_node(store, index, ray, tmin, tmax, shadow, hit, false);
    // The slot may have been taken by an inner member meanwhile: it is filled afresh.
    memo_slot(index) =
        NodeMemo{store.serial, index, shadow, result, ray.origin, ray.dir, tmin, tmax, hit};
    return result;
}

// Nearest hit ignoring the node's own clipped_by (`any`: the first member's accepted hit). The
// members themselves are always asked for their nearest hit: the retries from a rejected hit
// rely on it.
bool intersect_unclipped(const NodeStore& store, uint32_t index, const Ray& ray, double tmin,
                         double tmax, bool shadow, NodeHit& hit, bool any) {
    const Node& n = store.nodes[index];
    if (n.kind == NodeKind::Shape)
        return intersect_primitive(store, n, index, ray, tmin, tmax, shadow, hit);
    SlabRay slab(ray.origin, ray.dir);
    bool found = false;
    double best = tmax;
    for (uint32_t i = 0; i < n.child_count; ++i) {
        uint32_t c = store.links[n.children + i];
        const Aabb& box = store.nodes[c].surface;
        if (box.empty() || (box.finite() && !slab.hits(box, tmin, best))) continue;
        NodeHit h;
        double from = tmin;
        // A union rejects nothing, so its members too may answer with any hit.
        const bool member_any = any && n.kind == NodeKind::Union;
        for (int tries = 0; tries < kMaxRejected &&
                            intersect_member(store, c, ray, from, best, shadow, h, member_any);
             ++tries) {
            if (n.kind == NodeKind::Union || csg_accepts(store, n, i, ray.at(h.shape.t))) {
                best = h.shape.t;
                hit = h;
                found = true;
                break;
            }
            from = h.shape.t;  // rejected: look further along (strictly beyond it)
        }
        if (found && any) return true;
    }
    return found;
}

}  // namespace

uint64_t next_store_serial() {
    static std::atomic<uint64_t> next{1};
    return next++;
}

bool intersect_node(const NodeStore& store, uint32_t index, const Ray& ray, double tmin,
                    double tmax, bool shadow, NodeHit& hit, bool any) {
    const Node& n = store.nodes[index];
    // The common case (a plain primitive) without the retry loop.
    if (n.kind == NodeKind::Shape && n.clip_count == 0 && n.bound_count == 0)
        return intersect_primitive(store, n, index, ray, tmin, tmax, shadow, hit, any);
    if (n.bound_count && !ray_meets_bounds(store, n, ray)) return false;
    // Clipped: the retries from a clipped-away hit need the nearest one.
    any = any && n.clip_count == 0;
    double from = tmin;
    for (int tries = 0; tries < kMaxRejected &&
                        intersect_unclipped(store, index, ray, from, tmax, shadow, hit, any);
         ++tries) {
        if (n.clip_count == 0 || inside_all(store, n.clips, n.clip_count, ray.at(hit.shape.t)))
            return true;
        from = hit.shape.t;
    }
    return false;
}

bool inside_node(const NodeStore& store, uint32_t index, const glm::dvec3& p) {
    const Node& n = store.nodes[index];
    if (!n.solid.contains(p)) return false;
    bool in = false;
    switch (n.kind) {
    case NodeKind::Shape:
        in = shape_inside(store.shapes[n.shape], n.identity ? p : store.transforms[n.xf].inv_point(p));
        break;
    case NodeKind::Union:
    case NodeKind::Merge:
        for (uint32_t i = 0; i < n.child_count && !in; ++i)
            in = inside_node(store, store.links[n.children + i], p);
        break;
    case NodeKind::Intersection:
        in = n.child_count > 0;
        for (uint32_t i = 0; i < n.child_count && in; ++i)
            in = inside_node(store, store.links[n.children + i], p);
        break;
    }
    return (in != n.inverse) && inside_all(store, n.clips, n.clip_count, p);
}

}  // namespace lumen::render
