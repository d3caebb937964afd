// Bounding volume hierarchy over boxes (top-level objects, mesh triangles): binned SAH build,
// flattened depth-first nodes, traversal with a fixed stack and a caller-supplied leaf visitor
// (a template, so the per-primitive test inlines: no std::function, no allocation per ray).
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include "render/bounds.hpp"

namespace lumen::render {

struct BvhNode {
    Aabb box;
    uint32_t index = 0;  // leaf: first position in order(); inner: the second child's node
    uint16_t count = 0;  // primitives in a leaf; 0 for an inner node (first child = next node)
    uint8_t axis = 0;    // split axis, to visit the nearer child first
};

class Bvh {
public:
    // Builds over the primitives' boxes (in world or object space, as the caller likes).
    void build(const std::vector<Aabb>& boxes, int max_leaf = 4);

    // order()[i] = the primitive stored at position i (callers reorder their arrays by it).
    const std::vector<uint32_t>& order() const { return order_; }
    const std::vector<BvhNode>& nodes() const { return nodes_; }
    bool empty() const { return nodes_.empty(); }
    Aabb bounds() const { return nodes_.empty() ? Aabb{} : nodes_[0].box; }
    int depth() const { return depth_; }

    // Calls leaf(position) for the primitives of every leaf whose box the ray meets within
    // [tmin, tmax]. The visitor may lower tmax (nearest-hit search) to prune the rest.
    template <class Leaf>
    void traverse(const SlabRay& ray, double tmin, double& tmax, Leaf&& leaf) const {
        if (nodes_.empty() || !ray.hits(nodes_[0].box, tmin, tmax)) return;
        // Children are tested together; the nearer is visited first and the farther is
        // stacked with its entry distance, so it is skipped if a hit came closer meanwhile.
        struct Pending { uint32_t node; double enter; };
        Pending stack[kMaxDepth + 4];
        int sp = 0;
        uint32_t cur = 0;
        for (;;) {
            const BvhNode& n = nodes_[cur];
            if (n.count) {
                for (uint32_t i = n.index, e = n.index + n.count; i < e; ++i) leaf(i);
            } else {
                uint32_t a = cur + 1, b = n.index;
                double ta, tb, exit;
                bool hit_a = ray.hits(nodes_[a].box, tmin, tmax, ta, exit);
                bool hit_b = ray.hits(nodes_[b].box, tmin, tmax, tb, exit);
                if (hit_a && hit_b) {
                    if (tb < ta) {
                        std::swap(a, b);
                        std::swap(ta, tb);
                    }
                    stack[sp++] = {b, tb};
                    cur = a;
                    continue;
                }
                if (hit_a || hit_b) {
                    cur = hit_a ? a : b;
                    continue;
                }
            }
            for (;;) {  // next stacked node still in front of the nearest hit
                if (sp == 0) return;
                const Pending& p = stack[--sp];
                if (p.enter <= tmax) {
                    cur = p.node;
                    break;
                }
            }
        }
    }

    // Beyond this depth the build splits at the median, so depth stays below kMaxDepth.
    static constexpr int kSahDepth = 60;
    static constexpr int kMaxDepth = 100;

private:
    struct Prim;
    uint32_t build_range(std::vector<Prim>& prims, uint32_t begin, uint32_t end, int depth,
                         int max_leaf);
    std::vector<BvhNode> nodes_;
    std::vector<uint32_t> order_;
    int depth_ = 0;
};

}  // namespace lumen::render
