// Intersection and inside tests over compiled nodes: primitives, union, merge, intersection
// (difference = intersection with inverted subtrahends), clipped_by and bounded_by.
// A union asks its members for their nearest hits. A merge or intersection takes each CSG
// member's list of every hit along the ray (POV-Ray's depth lists) and keeps those the
// operation accepts: asking such a member again from beyond each rejected hit instead
// re-traced nested CSG once per rejection (advanced/grenadine's lemon slice: 235 primitive
// traces a ray against POV-Ray's 60). A plain primitive member is asked hit by hit. The lists
// live on a per-thread stack, so nothing is allocated per ray.
#include <algorithm>
#include <cmath>
#include <vector>

#include "render/node.hpp"

namespace lumen::render {

namespace {

// Asks of one primitive for its hits along a ray before the rest are given up on: a guard
// against a root finder that returns the same surface again an ulp further on, forever.
constexpr size_t kMaxListed = 1024;

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

// A primitive's nearest hit strictly beyond `from`: one that a shape working in its own
// units rounds back onto `from` (the hit asked from) is asked for again an ulp further.
bool next_primitive_hit(const NodeStore& store, const Node& n, uint32_t index, const Ray& ray,
                        double from, double hi, bool shadow, NodeHit& h) {
    for (int nudges = 0; nudges < 64; ++nudges) {
        if (!intersect_primitive(store, n, index, ray, from, hi, shadow, h)) return false;
        if (h.shape.t > from) return true;
        from = std::nextafter(from, hi);
    }
    return false;
}

// The thread's stack of hit lists: a list is built above those of the calls it is nested in
// and popped when its caller is done with it (kept by index: the stack may grow meanwhile).
std::vector<NodeHit>& hit_stack() {
    thread_local std::vector<NodeHit> stack;
    return stack;
}

// Keeps the hits in [first, end) of `hits` that `keep` accepts, in order.
template <class Keep> void keep_hits(std::vector<NodeHit>& hits, size_t first, Keep keep) {
    auto end = std::remove_if(hits.begin() + std::ptrdiff_t(first), hits.end(),
                              [&](const NodeHit& h) { return !keep(h); });
    hits.erase(end, hits.end());
}

// Merges the sorted list at [mid, end) of `hits` into the sorted one at [first, mid), ties
// in member order (the nearest-hit search's order), the end of the stack serving as scratch.
void merge_hits(std::vector<NodeHit>& hits, size_t first, size_t mid) {
    const size_t end = hits.size();
    if (mid == first || mid == end || !(hits[mid].shape.t < hits[mid - 1].shape.t)) return;
    hits.resize(end + (end - first));
    const auto at = [&](size_t i) { return hits.begin() + std::ptrdiff_t(i); };
    const auto by_t = [](const NodeHit& a, const NodeHit& b) { return a.shape.t < b.shape.t; };
    std::merge(at(first), at(mid), at(mid), at(end), at(end), by_t);
    std::move(at(end), hits.end(), at(first));
    hits.resize(end);
}

// Drops a hit at the distance of the one before it: a search from a hit looks strictly
// beyond it, so the member listed first is the one met.
void drop_repeats(std::vector<NodeHit>& hits, size_t first) {
    auto end = std::unique(hits.begin() + std::ptrdiff_t(first), hits.end(),
                           [](const NodeHit& a, const NodeHit& b) { return a.shape.t == b.shape.t; });
    hits.erase(end, hits.end());
}

// Where along the ray a hit of member i can be kept: within its own surface box and, in an
// intersection, inside every other member's solid box (widened by a rounding margin;
// csg_accepts decides exactly) and outside the interior of every subtracted box (a
// difference's inverse box member, untransformed, whose inside is exactly its slab interval,
// narrowed by the margin): the room a ray starts in, cut out of a wall block, rules out every
// other member's hits up to where the ray leaves it. Members beyond the first 16 are not
// looked at (the range is then only wider).
struct MemberRanges {
    static constexpr uint32_t kMax = 16;
    double enter[kMax], exit[kMax];
    double cut_lo[kMax], cut_hi[kMax];  // (cut_lo, cut_hi): inside a subtracted box
    uint32_t count = 0;
    bool any_cut = false;
    // The latest entry and earliest exit over the members, which member gives each, and the
    // same over the rest: a member's range is bounded by every other member's box in O(1).
    double latest = -Aabb::inf, next_latest = -Aabb::inf;
    double earliest = Aabb::inf, next_earliest = Aabb::inf;
    uint32_t latest_at = kMax, earliest_at = kMax;
    // The same over the finite boxes (and the missed ones) alone, for a member whose hits
    // depend on the range its search is given (Node::range_sensitive; kept only where the
    // intersection holds such a member).
    double latest_finite = -Aabb::inf, next_latest_finite = -Aabb::inf;
    double earliest_finite = Aabb::inf, next_earliest_finite = Aabb::inf;
    uint32_t latest_finite_at = kMax, earliest_finite_at = kMax;

    static void keep_latest(double e, uint32_t j, double& first, double& second, uint32_t& at) {
        if (e > first) second = first, first = e, at = j;
        else second = std::max(second, e);
    }
    static void keep_earliest(double x, uint32_t j, double& first, double& second, uint32_t& at) {
        if (x < first) second = first, first = x, at = j;
        else second = std::min(second, x);
    }

    static double margin(double t) { return 1e-6 * (1 + std::abs(t)); }

    MemberRanges(const NodeStore& store, const Node& n, const SlabRay& slab, double lo,
                 double hi) {
        if (n.kind != NodeKind::Intersection) return;
        count = std::min(n.child_count, kMax);
        for (uint32_t j = 0; j < count; ++j) {
            const Node& member = store.nodes[store.links[n.children + j]];
            const Aabb& box = member.solid;
            double e = lo, x = hi;
            if (!slab.hits(box, lo, hi, e, x)) {  // a half-space's box narrows too
                enter[j] = Aabb::inf, exit[j] = -Aabb::inf;  // no margin: inf - inf is NaN
            } else {
                enter[j] = e - margin(e);
                exit[j] = x + margin(x);
            }
            keep_latest(enter[j], j, latest, next_latest, latest_at);
            keep_earliest(exit[j], j, earliest, next_earliest, earliest_at);
            if (n.range_sensitive && (box.finite() || !(enter[j] < Aabb::inf))) {
                keep_latest(enter[j], j, latest_finite, next_latest_finite, latest_finite_at);
                keep_earliest(exit[j], j, earliest_finite, next_earliest_finite,
                              earliest_finite_at);
            }
            cut_lo[j] = Aabb::inf, cut_hi[j] = -Aabb::inf;
            if (const Aabb* cut = subtracted_box(store, member))
                if (slab.hits(*cut, -Aabb::inf, Aabb::inf, e, x)) {
                    cut_lo[j] = e + margin(e), cut_hi[j] = x - margin(x);
                    any_cut = any_cut || cut_lo[j] < cut_hi[j];
                }
        }
    }
    // An inverse, untransformed, unclipped box: its interior is exactly the slab interval.
    static const Aabb* subtracted_box(const NodeStore& store, const Node& m) {
        if (m.kind != NodeKind::Shape || !m.inverse || !m.identity || m.clip_count ||
            m.bound_count)
            return nullptr;
        const auto* box = std::get_if<BoxShape>(&store.shapes[m.shape]);
        return box && box->valid ? &box->box : nullptr;
    }
    // Narrows (lo, hi) for member i (node c); false when no hit of it can be kept there.
    bool narrow(const NodeStore& store, const SlabRay& slab, uint32_t i, uint32_t c, double& lo,
                double& hi) const {
        if (count > 0) {
            if (store.nodes[c].range_sensitive) {
                lo = std::max(lo, i == latest_finite_at ? next_latest_finite : latest_finite);
                hi = std::min(hi, i == earliest_finite_at ? next_earliest_finite : earliest_finite);
            } else {
                lo = std::max(lo, i == latest_at ? next_latest : latest);
                hi = std::min(hi, i == earliest_at ? next_earliest : earliest);
            }
        }
        // Cut intervals may chain (one box's exit inside the next): one pass per member.
        for (uint32_t pass = 0; any_cut && pass < count && lo < hi; ++pass) {
            bool moved = false;
            for (uint32_t j = 0; j < count; ++j) {
                if (j == i || !(cut_lo[j] < cut_hi[j])) continue;
                if (cut_lo[j] <= lo && lo < cut_hi[j]) lo = cut_hi[j], moved = true;
                if (cut_lo[j] < hi && hi <= cut_hi[j]) hi = cut_lo[j], moved = true;
            }
            if (!moved) break;
        }
        const Aabb& box = store.nodes[c].surface;
        return lo < hi && !box.empty() && (!box.finite() || slab.hits(box, lo, hi));
    }
};

// Appends every hit of node `index` in (lo, hi) that its operation, clipped_by and (with
// `check_bounds`) bounded_by keep, in increasing distance, each distance once.
void collect_hits(const NodeStore& store, uint32_t index, const Ray& ray, double lo, double hi,
                  bool shadow, bool check_bounds, std::vector<NodeHit>& out) {
    const Node& n = store.nodes[index];
    const size_t base = out.size();
    if (check_bounds && n.bound_count && !ray_meets_bounds(store, n, ray)) return;
    if (n.kind == NodeKind::Shape) {
        NodeHit h;
        for (double from = lo; out.size() - base < kMaxListed &&
                               next_primitive_hit(store, n, index, ray, from, hi, shadow, h);
             from = h.shape.t)
            out.push_back(h);
    } else {
        const SlabRay slab(ray.origin, ray.dir);
        const MemberRanges ranges(store, n, slab, lo, hi);
        for (uint32_t i = 0; i < n.child_count; ++i) {
            const uint32_t c = store.links[n.children + i];
            double from = lo, to = hi;
            if (!ranges.narrow(store, slab, i, c, from, to)) continue;
            const size_t first = out.size();
            collect_hits(store, c, ray, from, to, shadow, true, out);
            if (n.kind != NodeKind::Union)
                keep_hits(out, first, [&](const NodeHit& h) {
                    return csg_accepts(store, n, i, ray.at(h.shape.t));
                });
            merge_hits(out, base, first);
        }
        drop_repeats(out, base);
    }
    if (n.clip_count)
        keep_hits(out, base, [&](const NodeHit& h) {
            return inside_all(store, n.clips, n.clip_count, ray.at(h.shape.t));
        });
}

// The nearest hit of a union: each member's nearest (`any`: the first member's hit).
bool nearest_of_union(const NodeStore& store, const Node& n, const Ray& ray, double tmin,
                      double tmax, bool shadow, NodeHit& hit, bool any) {
    const SlabRay slab(ray.origin, ray.dir);
    bool found = false;
    double best = tmax;
    for (uint32_t i = 0; i < n.child_count; ++i) {
        const uint32_t c = store.links[n.children + i];
        const Aabb& box = store.nodes[c].surface;
        if (box.empty() || (box.finite() && !slab.hits(box, tmin, best))) continue;
        if (NodeHit h; intersect_node(store, c, ray, tmin, best, shadow, h, any)) {
            hit = h;
            best = h.shape.t;
            found = true;
            if (any) return true;
        }
    }
    return found;
}

// The nearest hit of a merge or intersection: each member's hits up to the best so far,
// tested in order until the operation accepts one (`any`: the first member's accepted hit).
bool nearest_of_members(const NodeStore& store, const Node& n, const Ray& ray, double tmin,
                        double tmax, bool shadow, NodeHit& hit, bool any) {
    std::vector<NodeHit>& stack = hit_stack();
    const SlabRay slab(ray.origin, ray.dir);
    const MemberRanges ranges(store, n, slab, tmin, tmax);
    bool found = false;
    double best = tmax;
    for (uint32_t i = 0; i < n.child_count && !(found && any); ++i) {
        const uint32_t c = store.links[n.children + i];
        double from = tmin, to = best;
        if (!ranges.narrow(store, slab, i, c, from, to)) continue;
        const auto kept = [&](const NodeHit& h) {
            if (!csg_accepts(store, n, i, ray.at(h.shape.t))) return false;
            hit = h;
            best = h.shape.t;
            found = true;
            return true;
        };
        const Node& member = store.nodes[c];
        if (member.kind == NodeKind::Shape && member.clip_count == 0 && member.bound_count == 0) {
            // A plain primitive is walked hit by hit: its first hit is often the one kept.
            NodeHit h;
            size_t asks = 0;
            for (double at = from; asks++ < kMaxListed &&
                                   next_primitive_hit(store, member, c, ray, at, to, shadow, h) &&
                                   !kept(h);
                 at = h.shape.t) {
            }
            continue;
        }
        const size_t first = stack.size();
        collect_hits(store, c, ray, from, to, shadow, true, stack);
        for (size_t k = first; k < stack.size() && !kept(stack[k]); ++k) {
        }
        stack.resize(first);
    }
    return found;
}

}  // namespace

bool intersect_node(const NodeStore& store, uint32_t index, const Ray& ray, double tmin,
                    double tmax, bool shadow, NodeHit& hit, bool any) {
    const Node& n = store.nodes[index];
    // The common case (a plain primitive) first.
    if (n.kind == NodeKind::Shape && n.clip_count == 0 && n.bound_count == 0)
        return intersect_primitive(store, n, index, ray, tmin, tmax, shadow, hit, any);
    if (n.bound_count && !ray_meets_bounds(store, n, ray)) return false;
    any = any && n.clip_count == 0;  // a clipped-away hit needs the nearest one
    bool found = false;
    switch (n.kind) {
    case NodeKind::Shape:
        found = intersect_primitive(store, n, index, ray, tmin, tmax, shadow, hit);
        break;
    case NodeKind::Union:
        found = nearest_of_union(store, n, ray, tmin, tmax, shadow, hit, any);
        break;
    case NodeKind::Merge:
    case NodeKind::Intersection:
        found = nearest_of_members(store, n, ray, tmin, tmax, shadow, hit, any);
        break;
    }
    if (!found) return false;
    if (n.clip_count == 0 || inside_all(store, n.clips, n.clip_count, ray.at(hit.shape.t)))
        return true;
    // Clipped away: the nearest of the node's hits beyond it that the clips keep.
    std::vector<NodeHit>& stack = hit_stack();
    const size_t first = stack.size();
    collect_hits(store, index, ray, hit.shape.t, tmax, shadow, false, stack);
    found = stack.size() > first;
    if (found) hit = stack[first];
    stack.resize(first);
    return found;
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
