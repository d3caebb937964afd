// Binned surface-area-heuristic BVH build (16 bins per axis, all three axes tried).
#include "render/bvh.hpp"

#include <algorithm>
#include <numeric>

namespace lumen::render {

namespace {

constexpr int kBins = 16;
constexpr double kTraversalCost = 1.0;  // relative to one primitive test

struct Bin {
    Aabb box;
    uint32_t count = 0;
};

}  // namespace

// Primitives are partitioned by value (box and centre together) so the build streams through
// memory instead of chasing indices.
struct Bvh::Prim {
    Aabb box;
    glm::dvec3 centre;
    uint32_t index;
};

void Bvh::build(const std::vector<Aabb>& boxes, int max_leaf) {
    nodes_.clear();
    depth_ = 0;
    order_.resize(boxes.size());
    std::iota(order_.begin(), order_.end(), 0u);
    if (boxes.empty()) return;
    std::vector<Prim> prims(boxes.size());
    for (size_t i = 0; i < boxes.size(); ++i) prims[i] = {boxes[i], boxes[i].centre(), uint32_t(i)};
    nodes_.reserve(2 * boxes.size());
    build_range(prims, 0, uint32_t(boxes.size()), 0, std::clamp(max_leaf, 1, 255));
    for (size_t i = 0; i < prims.size(); ++i) order_[i] = prims[i].index;
}

uint32_t Bvh::build_range(std::vector<Prim>& prims, uint32_t begin, uint32_t end, int depth,
                          int max_leaf) {
    depth_ = std::max(depth_, depth + 1);
    uint32_t self = uint32_t(nodes_.size());
    nodes_.emplace_back();
    Aabb box, cbox;
    for (uint32_t i = begin; i < end; ++i) {
        box.expand(prims[i].box);
        cbox.expand(prims[i].centre);
    }
    nodes_[self].box = box;
    uint32_t count = end - begin;
    auto make_leaf = [&] {
        nodes_[self].index = begin;
        nodes_[self].count = uint16_t(count);
        return self;
    };
    if (count <= 1) return make_leaf();

    // Best SAH split over all axes.
    int best_axis = -1, best_bin = 0;
    double best_cost = std::numeric_limits<double>::infinity();
    if (depth < kSahDepth) {
        for (int axis = 0; axis < 3; ++axis) {
            double lo = cbox.lo[axis], extent = cbox.hi[axis] - lo;
            if (!(extent > 0)) continue;
            Bin bins[kBins];
            double scale = kBins / extent;
            for (uint32_t i = begin; i < end; ++i) {
                int b = std::min(kBins - 1, int((prims[i].centre[axis] - lo) * scale));
                bins[b].count++;
                bins[b].box.expand(prims[i].box);
            }
            double right_area[kBins];
            uint32_t right_count[kBins];
            Aabb acc;
            uint32_t n = 0;
            for (int b = kBins - 1; b > 0; --b) {
                acc.expand(bins[b].box);
                n += bins[b].count;
                right_area[b] = acc.surface_area();
                right_count[b] = n;
            }
            acc = Aabb{};
            n = 0;
            for (int b = 0; b < kBins - 1; ++b) {
                acc.expand(bins[b].box);
                n += bins[b].count;
                if (n == 0 || right_count[b + 1] == 0) continue;
                double cost = n * acc.surface_area() + right_count[b + 1] * right_area[b + 1];
                if (cost < best_cost) {
                    best_cost = cost;
                    best_axis = axis;
                    best_bin = b;
                }
            }
        }
    }
    double area = box.surface_area();
    if (best_axis >= 0 && area > 0) {
        best_cost = kTraversalCost + best_cost / area;
        if (count <= uint32_t(max_leaf) && best_cost >= double(count)) return make_leaf();
    } else if (count <= uint32_t(max_leaf)) {
        return make_leaf();
    }

    uint32_t mid = begin;
    int axis = best_axis;
    if (best_axis >= 0) {
        double lo = cbox.lo[axis], scale = kBins / (cbox.hi[axis] - lo);
        auto it = std::partition(prims.begin() + begin, prims.begin() + end, [&](const Prim& p) {
            return std::min(kBins - 1, int((p.centre[axis] - lo) * scale)) <= best_bin;
        });
        mid = uint32_t(it - prims.begin());
    }
    if (mid == begin || mid == end) {  // no useful SAH split (or too deep): median by count
        glm::dvec3 ext = cbox.hi - cbox.lo;
        axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : (ext.y >= ext.z ? 1 : 2);
        mid = begin + count / 2;
        std::nth_element(prims.begin() + begin, prims.begin() + mid, prims.begin() + end,
                         [&](const Prim& a, const Prim& b) { return a.centre[axis] < b.centre[axis]; });
    }
    nodes_[self].axis = uint8_t(axis);
    build_range(prims, begin, mid, depth + 1, max_leaf);
    uint32_t right = build_range(prims, mid, end, depth + 1, max_leaf);
    nodes_[self].index = right;
    return self;
}

}  // namespace lumen::render
