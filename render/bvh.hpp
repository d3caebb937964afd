// Bounding volume hierarchy over boxes (top-level objects, mesh triangles): binned SAH build,
// flattened depth-first nodes, traversal with a fixed stack and a caller-supplied leaf visitor
// (a template, so the per-primitive test inlines: no std::function, no allocation per ray).
#pragma once
#include <cstdint>
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
        if (nodes_.empty()) return;
        uint32_t stack[kMaxDepth + 4];
        int sp = 0;
        uint32_t cur = 0;
        for (;;) {
            const BvhNode& n = nodes_[cur];
            if (ray.hits(n.box, tmin, tmax)) {
                if (n.count) {
                    for (uint32_t i = n.index, e = n.index + n.count; i < e; ++i) leaf(i);
                } else {
                    bool reverse = ray.inv_dir[n.axis] < 0;
                    stack[sp++] = reverse ? cur + 1 : n.index;
                    cur = reverse ? n.index : cur + 1;
                    continue;
                }
            }
            if (sp == 0) return;
            cur = stack[--sp];
        }
    }

    // Beyond this depth the build splits at the median, so depth stays below kMaxDepth.
    static constexpr int kSahDepth = 60;
    static constexpr int kMaxDepth = 100;

private:
    uint32_t build_range(const std::vector<Aabb>& boxes, const std::vector<glm::dvec3>& centres,
                         uint32_t begin, uint32_t end, int depth, int max_leaf);
    std::vector<BvhNode> nodes_;
    std::vector<uint32_t> order_;
    int depth_ = 0;
};

}  // namespace lumen::render
