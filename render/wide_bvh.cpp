#include "render/wide_bvh.hpp"

#include <limits>

namespace lumen::render {

namespace {

double half_area(const Aabb& b) {
    const glm::dvec3 e = b.hi - b.lo;
    return e.x * e.y + e.y * e.z + e.z * e.x;
}

}  // namespace

WideBvh::WideBvh(const Bvh& bvh) {
    if (bvh.empty()) return;
    nodes_.reserve(bvh.nodes().size() / 2 + 1);
    collapse(bvh, 0);
}

// The wide node for binary node `binary`: its children, the largest inner one opened into its
// own two children while there is room (the usual collapse), each slot then a leaf or a wide
// node of its own.
int32_t WideBvh::collapse(const Bvh& bvh, uint32_t binary) {
    const std::vector<BvhNode>& b = bvh.nodes();
    uint32_t slots[4];
    int n = 0;
    if (b[binary].count) {
        slots[n++] = binary;  // a leaf as the root: one slot
    } else {
        slots[n++] = binary + 1;
        slots[n++] = b[binary].index;
        while (n < 4) {
            int widest = -1;
            for (int k = 0; k < n; ++k)
                if (!b[slots[k]].count && (widest < 0 || half_area(b[slots[k]].box) > half_area(b[slots[widest]].box)))
                    widest = k;
            if (widest < 0) break;
            const uint32_t open = slots[widest];
            slots[widest] = open + 1;
            slots[n++] = b[open].index;
        }
    }
    const int32_t self = int32_t(nodes_.size());
    nodes_.emplace_back();
    constexpr double inf = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 4; ++k) {
        Node& node = nodes_[size_t(self)];
        node.child[k] = -1;
        node.count[k] = 0;
        for (int a = 0; a < 3; ++a) node.lo[a][k] = inf, node.hi[a][k] = -inf;
        if (k >= n) continue;
        const BvhNode& c = b[slots[k]];
        for (int a = 0; a < 3; ++a) node.lo[a][k] = c.box.lo[a], node.hi[a][k] = c.box.hi[a];
        node.used |= uint8_t(1u << k);
        if (c.count) {
            node.child[k] = int32_t(c.index);
            node.count[k] = c.count;
        } else {
            const int32_t child = collapse(bvh, slots[k]);  // (nodes_ may move: index again)
            nodes_[size_t(self)].child[k] = child;
        }
    }
    return self;
}

}  // namespace lumen::render
